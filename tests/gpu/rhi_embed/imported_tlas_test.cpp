// A host's TLAS imported by its native handle (importVulkanAccelStruct) on a wrapped device: the RHI
// queries its device address and traces it; every ray's (instance id, primitive id) must equal the CPU
// Moeller-Trumbore reference (tests/gpu/rhi_rt/cpu_ray_reference.h), except rays the reference marks
// ambiguous (within 1e-4 barycentric of an edge, the bound rhi_rt's triangle tests derive).
#include <gtest/gtest.h>

#include <random>

#include "caustics/rhi/vulkan_interop.h"
#include "raw_vulkan_host.h"
#include "rt_test_support.h"

namespace caustics::test {
namespace {
using namespace rhi;

constexpr double kEdgeEpsilon = 1e-4;

TEST(ImportedTlas, IsTracedOnTheWrappedDeviceLikeTheCpuReference) {
    RawVulkanHost host;
    ASSERT_TRUE(host.create(/*withRayTracing=*/true)) << host.why();
    {
        auto wrapped = wrapVulkanDevice(host.deviceImport());
        ASSERT_TRUE(wrapped.ok()) << wrapped.message();
        IDevice& device = *wrapped.value();

        // "The host's" TLAS: built here, then handed to the RHI only as a VkAccelerationStructureKHR.
        const CpuMesh terrain = makeTerrain(6, 0.2f);
        std::vector<BufferHandle> keepAlive;
        AccelStructHandle blas = makeTriangleBlas(device, terrain, AccelBuildFlags::PreferFastTrace, keepAlive);
        ASSERT_TRUE(blas);
        const std::vector<CpuInstance> cpu = {{&terrain, makeTransform(0.1, -0.2, 0.3, {1, 1, 1}, {0, 0, 0}), 11}};
        InstanceDesc instance;
        writeTransform(cpu[0].transform, instance);
        instance.instanceId = cpu[0].instanceId;
        instance.blasAddress = blas->deviceAddress();
        AccelStructDesc tlasDesc;
        tlasDesc.isTopLevel = true;
        tlasDesc.maxInstances = 1;
        auto hostTlas = device.createAccelStruct(tlasDesc);
        ASSERT_TRUE(hostTlas.ok()) << hostTlas.message();
        ASSERT_TRUE(runAndWait(device, [&](ICommandList& cmd) {
            cmd.buildBottomLevel(blas);
            cmd.barrier(AccelStructBarrier{blas, ResourceState::AccelStructWrite, ResourceState::AccelStructRead});
            cmd.buildTopLevel(hostTlas.value(), std::span(&instance, 1));
            cmd.barrier(AccelStructBarrier{hostTlas.value(), ResourceState::AccelStructWrite, ResourceState::AccelStructRead});
        }));
        const auto native = hostTlas.value()->getNativeObject(NativeObjectType::VkAccelerationStructureKHR);
        ASSERT_TRUE(native.valid());

        auto imported = importVulkanAccelStruct(device, {.accelStruct = native.as<VkAccelerationStructureKHR>(),
                                                         .debugName = "host TLAS"});
        ASSERT_TRUE(imported.ok()) << imported.message();
        EXPECT_EQ(imported.value()->deviceAddress(), hostTlas.value()->deviceAddress());
        EXPECT_EQ(imported.value()->getNativeObject(NativeObjectType::VkAccelerationStructureKHR).handle, native.handle);

        std::mt19937 rng(9);
        std::uniform_real_distribution<double> u(-1.1, 1.1), tilt(-0.2, 0.2);
        RayList rays;
        for (int i = 0; i < 1024; ++i) rays.add({u(rng), u(rng), 3.0}, {tilt(rng), tilt(rng), -1.0}, 0.0f, 100.0f);
        const auto gpu = traceRayList(device, imported.value(), rays);
        ASSERT_EQ(gpu.size(), rays.count());
        uint32_t hits = 0, mismatches = 0, ambiguous = 0;
        for (uint32_t i = 0; i < rays.count(); ++i) {
            const CpuHit ref = traceCpu(cpu, rays.origin(i), rays.direction(i), 0.0, 100.0, kEdgeEpsilon);
            if (ref.ambiguous) {
                ++ambiguous;
                continue;
            }
            const uint32_t expectedInstance = ref.hit ? ref.instanceId : ~0u;
            const uint32_t expectedPrimitive = ref.hit ? ref.primitiveId : ~0u;
            hits += ref.hit;
            if ((gpu[i][0] != expectedInstance || gpu[i][1] != expectedPrimitive) && ++mismatches <= 5)
                ADD_FAILURE() << "ray " << i << ": GPU (" << gpu[i][0] << ", " << gpu[i][1] << "), CPU (" << expectedInstance
                              << ", " << expectedPrimitive << ")";
        }
        EXPECT_EQ(mismatches, 0u);
        EXPECT_GT(hits, rays.count() / 2) << "the terrain covers most of the ray footprint";
        EXPECT_LT(ambiguous, rays.count() / 50);
        // The import is dropped first: the original (the "host's") must still be valid, which the
        // layer checks when the RHI destroys it below.
    }
    host.destroyAll();
    std::vector<std::string> seen = host.messages();
    std::string all;
    for (const std::string& m : seen) all += "\n  " + m;
    EXPECT_TRUE(seen.empty()) << seen.size() << " validation message(s):" << all;
}

}  // namespace
}  // namespace caustics::test
