#pragma once
// Instance creation (validation layer with synchronization validation, debug messenger) and the
// physical-device choice. Split from the device so each reads in one sitting.
#include "vk_context.h"

namespace caustics::rhi::vulkan {

// Creates context.instance (+ messenger) and loads the instance-level entry points into context.fn.
Status createInstance(VulkanContext& context, const DeviceDesc& desc);
// Picks a physical device with everything `desc` needs, creates the VkDevice, queue, timeline
// semaphore, fills properties/capabilities and loads the device-level entry points.
Status createLogicalDevice(VulkanContext& context, const DeviceDesc& desc);

}  // namespace caustics::rhi::vulkan
