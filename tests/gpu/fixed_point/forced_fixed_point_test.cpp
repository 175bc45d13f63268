// CAUSTICS_FORCE_FIXED_POINT (docs/d3d12.md) turns the Vulkan device's float-atomic capability off,
// which is what selects the fixed-point caustic shaders (passes/caustic_maps/caustic_resources.cpp).
// The FixedPoint.* CTest entries rely on it; this checks that it works.
#include <cstdlib>

#include <gtest/gtest.h>

#include "caustics/rhi/rhi.h"

namespace caustics::test {
namespace {

TEST(ForcedFixedPoint, EnvironmentSwitchReportsNoFloatAtomicAdd) {
    ASSERT_EQ(setenv("CAUSTICS_FORCE_FIXED_POINT", "1", 1), 0);
    rhi::DeviceDesc desc;
    desc.backend = rhi::Backend::Vulkan;
    auto device = rhi::createDevice(desc);
    unsetenv("CAUSTICS_FORCE_FIXED_POINT");
    ASSERT_TRUE(device.ok()) << device.message();
    EXPECT_FALSE(device.value()->capabilities().shaderFloatAtomicAdd);
}

TEST(ForcedFixedPoint, ZeroLeavesTheDeviceCapabilityAsQueried) {
    auto queried = rhi::createDevice(rhi::DeviceDesc{});
    ASSERT_TRUE(queried.ok()) << queried.message();
    ASSERT_EQ(setenv("CAUSTICS_FORCE_FIXED_POINT", "0", 1), 0);
    auto withZero = rhi::createDevice(rhi::DeviceDesc{});
    unsetenv("CAUSTICS_FORCE_FIXED_POINT");
    ASSERT_TRUE(withZero.ok()) << withZero.message();
    EXPECT_EQ(withZero.value()->capabilities().shaderFloatAtomicAdd, queried.value()->capabilities().shaderFloatAtomicAdd);
}

}  // namespace
}  // namespace caustics::test
