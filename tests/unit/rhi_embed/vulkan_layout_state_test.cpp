// resourceStateFromVkImageLayout: every layout it accepts comes back unchanged from the backend's own
// state translation (vk_resource_state.h), so the render graph's first barrier names the host's real
// layout and its last one leaves exactly the layout the host declared.
#include <gtest/gtest.h>

#include "caustics/rhi/vulkan_interop.h"
#include "vk_resource_state.h"

namespace caustics::rhi {
namespace {

TEST(VulkanLayoutState, EveryAcceptedColourLayoutRoundTrips) {
    for (VkImageLayout layout : {VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                 VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR}) {
        auto state = resourceStateFromVkImageLayout(layout);
        ASSERT_TRUE(state.ok()) << "layout " << layout << ": " << state.message();
        EXPECT_EQ(vulkan::translateState(state.value(), false).layout, layout) << "layout " << layout;
    }
}

TEST(VulkanLayoutState, EveryAcceptedDepthLayoutRoundTrips) {
    for (VkImageLayout layout : {VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                                 VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL}) {
        auto state = resourceStateFromVkImageLayout(layout, true);
        ASSERT_TRUE(state.ok()) << "layout " << layout << ": " << state.message();
        EXPECT_EQ(vulkan::translateState(state.value(), true).layout, layout) << "layout " << layout;
    }
}

TEST(VulkanLayoutState, UndefinedMeansContentsMayBeDiscarded) {
    auto state = resourceStateFromVkImageLayout(VK_IMAGE_LAYOUT_UNDEFINED);
    ASSERT_TRUE(state.ok());
    EXPECT_EQ(state.value(), ResourceState::Undefined);
}

TEST(VulkanLayoutState, LayoutsTheRhiCannotReproduceAreRefusedByName) {
    auto depthSampled = resourceStateFromVkImageLayout(VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, true);
    ASSERT_FALSE(depthSampled.ok());
    EXPECT_NE(depthSampled.message().find("DEPTH_STENCIL_READ_ONLY_OPTIMAL"), std::string::npos);
    auto separate = resourceStateFromVkImageLayout(VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, true);
    ASSERT_FALSE(separate.ok());
    EXPECT_NE(separate.message().find("has no RHI state"), std::string::npos) << separate.message();
}

}  // namespace
}  // namespace caustics::rhi
