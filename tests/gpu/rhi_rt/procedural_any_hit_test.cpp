// Procedural geometry: a BLAS of thousands of sphere AABBs, an intersection shader for spheres and an
// any-hit shader that counts every sphere containing the ray origin and ignores the hit so that
// traversal goes on. The counts must equal a CPU brute-force count for every query point.
#include <gtest/gtest.h>

#include <random>

#include "rt_fixture.h"

namespace caustics::test {
namespace {

using namespace caustics::rhi;

constexpr uint32_t kSpheres = 3000;
constexpr uint32_t kPoints = 4096;
// Points this close to a sphere's surface (in |p - c|^2 - r^2) are regenerated: float rounding of the
// GPU's and CPU's expressions (a few ulp of values <= 3, ~1e-6) could disagree there.
constexpr float kSurfaceMargin = 1e-5f;

float containment(const std::array<float, 4>& s, const std::array<float, 4>& p) {
    const float dx = p[0] - s[0], dy = p[1] - s[1], dz = p[2] - s[2];
    return dx * dx + dy * dy + dz * dz - s[3] * s[3];
}

TEST_F(RayTracingTest, AnyHitCountsEverySphereContainingEachPointExactlyOnce) {
    std::mt19937 rng(2024);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f), radius(0.03f, 0.12f);
    std::vector<std::array<float, 4>> spheres(kSpheres);
    std::vector<float> aabbs;
    for (auto& s : spheres) {
        s = {unit(rng), unit(rng), unit(rng), radius(rng)};
        aabbs.insert(aabbs.end(), {s[0] - s[3], s[1] - s[3], s[2] - s[3], s[0] + s[3], s[1] + s[3], s[2] + s[3]});
    }
    std::vector<std::array<float, 4>> points(kPoints);
    std::vector<uint32_t> expected(kPoints, 0);
    for (uint32_t i = 0; i < kPoints; ++i) {
        for (bool clear = false; !clear;) {
            points[i] = {unit(rng), unit(rng), unit(rng), 0};
            clear = true;
            expected[i] = 0;
            for (const auto& s : spheres) {
                const float c = containment(s, points[i]);
                if (std::abs(c) < kSurfaceMargin) clear = false;
                expected[i] += c < 0 ? 1 : 0;
            }
        }
    }

    std::vector<BufferHandle> keep;
    keep.push_back(makeUploadBuffer(dev(), aabbs, BufferUsage::AccelStructInput, "sphere AABBs"));
    AccelStructDesc blasDesc;
    blasDesc.geometries.push_back(GeometryDesc::fromAabbs({keep.back(), 0, kSpheres, 24}, GeometryFlags::NoDuplicateAnyHit));
    auto blas = dev().createAccelStruct(blasDesc);
    ASSERT_TRUE(blas) << blas.message();
    AccelStructDesc tlasDesc;
    tlasDesc.isTopLevel = true;
    tlasDesc.maxInstances = 1;
    auto tlas = dev().createAccelStruct(tlasDesc);
    ASSERT_TRUE(tlas) << tlas.message();
    InstanceDesc instance;
    instance.blasAddress = blas.value()->deviceAddress();

    StateObjectDesc desc;
    desc.libraries.push_back(shaderLibrary("rt/sphere_count.rgen", "rayGen", ShaderStage::RayGen));
    desc.libraries.push_back(shaderLibrary("rt/sphere_count.rmiss", "miss", ShaderStage::Miss));
    desc.libraries.push_back(shaderLibrary("rt/sphere.rint", "sphere", ShaderStage::Intersection));
    desc.libraries.push_back(shaderLibrary("rt/sphere_count.rahit", "count", ShaderStage::AnyHit));
    desc.hitGroups.push_back({"spheres", HitGroupType::Procedural, "", "count", "sphere"});
    desc.maxPayloadBytes = 4;
    BindingLayoutHandle layout = makeLayout(dev(), 2);
    desc.globalBindings.layouts = {layout};
    auto so = dev().createStateObject(desc);
    ASSERT_TRUE(so) << so.message();
    auto table = dev().createShaderTable(ShaderTableDesc{so.value()}.setRayGen("rayGen").addMiss("miss").addHitGroup("spheres"));
    ASSERT_TRUE(table) << table.message();

    BufferHandle sphereBuffer = makeUploadBuffer(dev(), spheres, BufferUsage::Storage, "spheres");
    BufferHandle pointBuffer = makeUploadBuffer(dev(), points, BufferUsage::Storage, "points");
    BufferHandle counts = makeOutputBuffer(dev(), kPoints * 4, "counts");
    BufferHandle readback = makeReadbackBuffer(dev(), kPoints * 4);
    auto set = dev().createBindingSet(BindingSetDesc()
                                          .add(BindingSetItem::accelStructItem(0, tlas.value()))
                                          .add(BindingSetItem::storageBuffer(1, counts))
                                          .add(BindingSetItem::storageBuffer(2, sphereBuffer, false))
                                          .add(BindingSetItem::storageBuffer(3, pointBuffer, false)),
                                      layout);
    ASSERT_TRUE(set) << set.message();

    ASSERT_TRUE(runAndWait(dev(), [&](ICommandList& cmd) {
        cmd.buildBottomLevel(blas.value());
        cmd.barrier(AccelStructBarrier{blas.value(), ResourceState::AccelStructWrite, ResourceState::AccelStructRead});
        cmd.buildTopLevel(tlas.value(), std::span(&instance, 1));
        cmd.barrier(AccelStructBarrier{tlas.value(), ResourceState::AccelStructWrite, ResourceState::AccelStructRead});
        recordClear(cmd, counts);
        cmd.setRayTracingState(so.value(), table.value());
        cmd.setBindingSet(0, set.value());
        cmd.dispatchRays(kPoints);
        recordReadback(cmd, counts, readback, kPoints * 4);
    }));
    auto got = readBack<uint32_t>(dev(), readback, kPoints);
    ASSERT_EQ(got.size(), size_t(kPoints));
    uint32_t wrong = 0, total = 0;
    for (uint32_t i = 0; i < kPoints; ++i) {
        total += expected[i];
        if (got[i] != expected[i] && ++wrong <= 10)
            ADD_FAILURE() << "point " << i << ": GPU counted " << got[i] << " spheres, CPU " << expected[i];
    }
    EXPECT_EQ(wrong, 0u);
    EXPECT_GT(total, kPoints) << "spheres too sparse: the test would not exercise multiple any-hits per ray";
}

}  // namespace
}  // namespace caustics::test
