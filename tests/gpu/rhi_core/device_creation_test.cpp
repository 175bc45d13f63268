// Device creation refuses a device that lacks a required extension, naming it, without crashing.
#include <gtest/gtest.h>

#include "caustics/rhi/rhi.h"

namespace caustics::test {
namespace {
using namespace rhi;

DeviceDesc quietDesc() {
    DeviceDesc desc;
    desc.backend = Backend::Vulkan;
    desc.requireRayTracing = true;
    desc.validationCallback = [](LogLevel, std::string_view) {};
    return desc;
}

TEST(VulkanDeviceCreation, UnknownRequiredExtensionIsRefusedByName) {
    DeviceDesc desc = quietDesc();
    desc.requiredExtensions = {"VK_EXT_this_extension_does_not_exist"};
    auto device = createDevice(desc);
    ASSERT_FALSE(device.ok());
    EXPECT_NE(device.message().find("VK_EXT_this_extension_does_not_exist"), std::string::npos) << device.message();
    EXPECT_NE(device.message().find("requiredExtensions"), std::string::npos) << device.message();
}

// VK_NV_ray_tracing (the NVIDIA-only predecessor of the KHR extension) exists, but not on lavapipe.
TEST(VulkanDeviceCreation, RealExtensionMissingOnLavapipeIsRefusedByName) {
    DeviceDesc desc = quietDesc();
    desc.requiredExtensions = {"VK_NV_ray_tracing"};
    auto device = createDevice(desc);
    if (device.ok() && device.value()->capabilities().adapterName.find("llvmpipe") == std::string::npos)
        GTEST_SKIP() << "this device has VK_NV_ray_tracing; the refusal is checked on lavapipe";
    ASSERT_FALSE(device.ok());
    EXPECT_NE(device.message().find("VK_NV_ray_tracing"), std::string::npos) << device.message();
    EXPECT_NE(device.message().find("llvmpipe"), std::string::npos) << device.message();
}

TEST(VulkanDeviceCreation, RayTracingDeviceReportsItsCapabilities) {
    auto device = createDevice(quietDesc());
    ASSERT_TRUE(device.ok()) << device.message();
    const Capabilities& caps = device.value()->capabilities();
    EXPECT_TRUE(caps.rayTracingPipeline);
    EXPECT_TRUE(caps.accelerationStructure);
    EXPECT_GE(caps.shaderGroupHandleSize, 16u);
    EXPECT_GT(caps.timestampPeriodNs, 0.0);
    EXPECT_GT(caps.maxInstanceCount, 0u);
    EXPECT_FALSE(caps.adapterName.empty());
}

}  // namespace
}  // namespace caustics::test
