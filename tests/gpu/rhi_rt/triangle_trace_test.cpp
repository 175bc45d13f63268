// A BLAS of triangles instanced three times with different transforms, traced by a raygen / miss /
// closest-hit state object at 128x128; every pixel's (instance id, primitive id) is compared with a
// CPU Moeller-Trumbore reference.
#include <gtest/gtest.h>

#include <map>

#include "rt_fixture.h"

namespace caustics::test {
namespace {

using namespace caustics::rhi;

constexpr uint32_t kSize = 128;
// A ray within this barycentric distance of an edge may hit either neighbour (or miss) on the GPU:
// lavapipe transforms the ray into object space in float (relative error ~1e-7 per operation over a
// handful of operations) and uses a watertight float test, so its barycentrics differ from the double
// CPU ones by ~1e-6. 1e-4 leaves two orders of magnitude of margin yet excludes only pixels whose
// centre lies within ~1e-4 of a triangle size from an edge (well under 1% of the image, checked below).
constexpr double kEdgeEpsilon = 1e-4;

struct Camera {
    float origin[4] = {0, 0, 5, 0};
    float lowerLeft[4] = {-0.4f, -0.4f, -1, 0};
    float du[4] = {0.8f / kSize, 0, 0, 0};
    float dv[4] = {0, 0.8f / kSize, 0, 0};
};

TEST_F(RayTracingTest, TrianglesOfInstancedBlasMatchCpuReferenceEveryPixel) {
    const CpuMesh terrain = makeTerrain(8, 0.15f);
    std::vector<BufferHandle> keepAlive;
    AccelStructHandle blas = makeTriangleBlas(dev(), terrain, AccelBuildFlags::PreferFastTrace, keepAlive);
    ASSERT_TRUE(blas);

    // Three instances: plain, rotated/scaled in front of the first, and mirrored (negative determinant).
    std::vector<CpuInstance> cpu = {
        {&terrain, makeTransform(0.0, 0.0, 0.35, {1, 1, 1}, {-0.5, 0, 0}), 7},
        {&terrain, makeTransform(0.2, 0.5, -0.3, {0.7, 0.7, 0.7}, {0.6, 0.3, 1.0}), 42},
        {&terrain, makeTransform(0.0, 0.0, 0.0, {0.5, -0.5, 0.5}, {-1.2, 1.2, -0.5}), 99},
    };
    std::vector<InstanceDesc> instances(cpu.size());
    for (size_t i = 0; i < cpu.size(); ++i) {
        writeTransform(cpu[i].transform, instances[i]);
        instances[i].instanceId = cpu[i].instanceId;
        instances[i].blasAddress = blas->deviceAddress();
    }
    AccelStructDesc tlasDesc;
    tlasDesc.isTopLevel = true;
    tlasDesc.maxInstances = uint32_t(instances.size());
    auto tlas = dev().createAccelStruct(tlasDesc);
    ASSERT_TRUE(tlas) << tlas.message();

    BindingLayoutHandle layout = makeLayout(dev(), 0);
    StateObjectHandle so = makeHitInfoStateObject(dev(), "rt/camera.rgen", layout, sizeof(Camera));
    ASSERT_TRUE(so);
    ShaderTableHandle table = makeHitInfoTable(dev(), so);
    ASSERT_TRUE(table);
    const uint64_t outBytes = uint64_t(kSize) * kSize * 8;
    BufferHandle out = makeOutputBuffer(dev(), outBytes, "hits");
    BufferHandle readback = makeReadbackBuffer(dev(), outBytes);
    auto set = dev().createBindingSet(
        BindingSetDesc().add(BindingSetItem::accelStructItem(0, tlas.value())).add(BindingSetItem::storageBuffer(1, out)),
        layout);
    ASSERT_TRUE(set) << set.message();

    const Camera camera;
    ASSERT_TRUE(runAndWait(dev(), [&](ICommandList& cmd) {
        cmd.buildBottomLevel(blas);
        cmd.barrier(AccelStructBarrier{blas, ResourceState::AccelStructWrite, ResourceState::AccelStructRead});
        cmd.buildTopLevel(tlas.value(), instances);
        cmd.barrier(AccelStructBarrier{tlas.value(), ResourceState::AccelStructWrite, ResourceState::AccelStructRead});
        recordClear(cmd, out);
        cmd.setRayTracingState(so, table);
        cmd.setBindingSet(0, set.value());
        cmd.setPushConstants(&camera, sizeof(camera));
        cmd.dispatchRays(kSize, kSize);
        recordReadback(cmd, out, readback, outBytes);
    }));
    auto gpu = readBack<std::array<uint32_t, 2>>(dev(), readback, size_t(kSize) * kSize);
    ASSERT_EQ(gpu.size(), size_t(kSize) * kSize);

    uint32_t ambiguous = 0, mismatches = 0, misses = 0;
    std::map<uint32_t, uint32_t> pixelsPerInstance;
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            Vec3 dir;
            for (int k = 0; k < 3; ++k)
                dir[k] = float(camera.lowerLeft[k] + (float(x) + 0.5f) * camera.du[k] + (float(y) + 0.5f) * camera.dv[k]);
            const CpuHit ref = traceCpu(cpu, {0, 0, 5}, dir, 0.0, 1e30, kEdgeEpsilon);
            const auto& got = gpu[y * kSize + x];
            if (ref.ambiguous) {
                ++ambiguous;
                continue;
            }
            const uint32_t wantInstance = ref.hit ? ref.instanceId : ~0u;
            const uint32_t wantPrimitive = ref.hit ? ref.primitiveId : ~0u;
            if (got[0] != wantInstance || got[1] != wantPrimitive) {
                if (++mismatches <= 10)
                    ADD_FAILURE() << "pixel (" << x << ", " << y << "): GPU (" << got[0] << ", " << got[1] << "), CPU ("
                                  << wantInstance << ", " << wantPrimitive << ")";
            }
            if (ref.hit) ++pixelsPerInstance[ref.instanceId];
            else ++misses;
        }
    }
    EXPECT_EQ(mismatches, 0u);
    EXPECT_LT(ambiguous, kSize * kSize / 100) << "too many edge pixels for the comparison to mean much";
    // The scene must exercise every instance and the miss shader, or the comparison proves little.
    for (const CpuInstance& inst : cpu) EXPECT_GT(pixelsPerInstance[inst.instanceId], 200u) << inst.instanceId;
    EXPECT_GT(misses, 200u);
}

}  // namespace
}  // namespace caustics::test
