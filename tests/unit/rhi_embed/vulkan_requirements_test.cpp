// readVulkanFeatureChain and checkVulkanDeviceRequirements: a host's feature chain is read whichever
// structures carry the features, and one refusal names every missing version, extension and feature.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "caustics/rhi/vulkan_interop.h"

namespace caustics::rhi {
namespace {

const std::vector<std::string> kRayTracingExtensions = {VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME,
                                                        VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
                                                        VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME};

VulkanEnabledFeatures everything() {
    VulkanEnabledFeatures f;
    f.bufferDeviceAddress = f.runtimeDescriptorArray = f.shaderSampledImageArrayNonUniformIndexing = true;
    f.descriptorBindingPartiallyBound = f.timelineSemaphore = f.hostQueryReset = true;
    f.dynamicRendering = f.synchronization2 = f.accelerationStructure = f.rayTracingPipeline = true;
    return f;
}

TEST(VulkanFeatureChain, ReadsCoreVersionStructures) {
    VkPhysicalDeviceFeatures2 base{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    base.pNext = &v12;
    v12.pNext = &v13;
    v12.bufferDeviceAddress = v12.timelineSemaphore = VK_TRUE;
    v13.synchronization2 = VK_TRUE;
    const VulkanEnabledFeatures f = readVulkanFeatureChain(&base);
    EXPECT_TRUE(f.bufferDeviceAddress);
    EXPECT_TRUE(f.timelineSemaphore);
    EXPECT_TRUE(f.synchronization2);
    EXPECT_FALSE(f.dynamicRendering);
    EXPECT_FALSE(f.hostQueryReset);
    EXPECT_FALSE(f.rayTracingPipeline);
}

TEST(VulkanFeatureChain, ReadsPerExtensionStructuresAndSkipsUnknownOnes) {
    VkPhysicalDeviceBufferDeviceAddressFeatures bda{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_BUFFER_DEVICE_ADDRESS_FEATURES};
    VkPhysicalDeviceMeshShaderFeaturesEXT unknown{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MESH_SHADER_FEATURES_EXT};
    VkPhysicalDeviceRayTracingPipelineFeaturesKHR rt{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
    VkPhysicalDeviceAccelerationStructureFeaturesKHR as{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
    VkPhysicalDeviceShaderAtomicFloatFeaturesEXT atomics{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_ATOMIC_FLOAT_FEATURES_EXT};
    bda.pNext = &unknown;
    unknown.pNext = &rt;
    rt.pNext = &as;
    as.pNext = &atomics;
    bda.bufferDeviceAddress = VK_TRUE;
    rt.rayTracingPipeline = VK_TRUE;
    as.accelerationStructure = VK_FALSE;
    atomics.shaderBufferFloat32AtomicAdd = VK_TRUE;
    const VulkanEnabledFeatures f = readVulkanFeatureChain(&bda);
    EXPECT_TRUE(f.bufferDeviceAddress);
    EXPECT_TRUE(f.rayTracingPipeline);
    EXPECT_FALSE(f.accelerationStructure);
    EXPECT_TRUE(f.shaderBufferFloat32AtomicAdd);
    EXPECT_FALSE(f.shaderImageFloat32AtomicAdd);
}

TEST(VulkanDeviceRequirements, CompleteDeviceIsAccepted) {
    EXPECT_TRUE(checkVulkanDeviceRequirements(VK_API_VERSION_1_3, kRayTracingExtensions, everything(), true, "gpu").ok());
}

TEST(VulkanDeviceRequirements, OneErrorNamesEveryMissingPiece) {
    VulkanEnabledFeatures f = everything();
    f.hostQueryReset = false;
    f.rayTracingPipeline = false;
    const std::vector<std::string> extensions = {VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME};
    Status s = checkVulkanDeviceRequirements(VK_API_VERSION_1_2, extensions, f, true, "old gpu");
    ASSERT_FALSE(s.ok());
    for (const char* name : {"'old gpu'", "1.2 (needs 1.3)", "VK_KHR_ray_tracing_pipeline", "VK_KHR_deferred_host_operations",
                             "hostQueryReset", "rayTracingPipeline"})
        EXPECT_NE(s.message().find(name), std::string::npos) << "missing '" << name << "' in: " << s.message();
    // What is there is not named.
    EXPECT_EQ(s.message().find("VK_KHR_acceleration_structure"), std::string::npos) << s.message();
    EXPECT_EQ(s.message().find("synchronization2"), std::string::npos) << s.message();
}

TEST(VulkanDeviceRequirements, RayTracingIsNotAskedForWhenNotRequired) {
    VulkanEnabledFeatures f = everything();
    f.accelerationStructure = f.rayTracingPipeline = false;
    EXPECT_TRUE(checkVulkanDeviceRequirements(VK_API_VERSION_1_3, {}, f, false, "raster gpu").ok());
    EXPECT_FALSE(checkVulkanDeviceRequirements(VK_API_VERSION_1_3, {}, f, true, "raster gpu").ok());
}

TEST(VulkanDeviceRequirements, FloatAtomicsAreOptional) {
    // The module falls back to fixed-point accumulation (radiance_atomics), so they never refuse a device.
    VulkanEnabledFeatures f = everything();
    f.shaderBufferFloat32AtomicAdd = f.shaderImageFloat32AtomicAdd = false;
    EXPECT_TRUE(checkVulkanDeviceRequirements(VK_API_VERSION_1_3, kRayTracingExtensions, f, true, "gpu").ok());
}

}  // namespace
}  // namespace caustics::rhi
