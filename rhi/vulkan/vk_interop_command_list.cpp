// Recording into a host engine's VkCommandBuffer (vulkan_interop.h): the wrapped list records like
// ours, and the host learns when to signal our timeline so deferred destruction and the list's
// staging buffers follow its submission.
#include <string>

#include "caustics/rhi/vulkan_interop.h"
#include "vk_command_list.h"
#include "vk_device.h"

namespace caustics::rhi {

Result<CommandListHandle> wrapVulkanCommandBuffer(IDevice& device, const VulkanCommandBufferImport& desc) {
    if (device.backend() != Backend::Vulkan)
        return makeError("wrapVulkanCommandBuffer '" + desc.debugName + "': the device is not a Vulkan device");
    if (desc.commandBuffer == VK_NULL_HANDLE)
        return makeError("wrapVulkanCommandBuffer '" + desc.debugName + "': commandBuffer is VK_NULL_HANDLE");
    auto& vk = static_cast<vulkan::VulkanDevice&>(device);
    return CommandListHandle(vulkan::VulkanCommandList::wrap(vk, desc.commandBuffer, desc.allowTimestamps));
}

Result<VulkanSubmitSignal> vulkanSubmitSignal(IDevice& device, ICommandList& wrapped) {
    if (device.backend() != Backend::Vulkan) return makeError("vulkanSubmitSignal: the device is not a Vulkan device");
    auto& list = static_cast<vulkan::VulkanCommandList&>(wrapped);
    auto& vk = static_cast<vulkan::VulkanDevice&>(device);
    if (!list.isWrapped())
        return makeError("vulkanSubmitSignal: the command list is the module's own; IDevice::submit signals for it");
    if (&list.context() != &vk.context())
        return makeError("vulkanSubmitSignal: the command list was wrapped on another device");
    // Recording errors surface here: the host's submit is the first point after recording we see.
    if (list.recordingError()) return list.recordingError().value();
    vulkan::VulkanContext& ctx = vk.context();
    const uint64_t value = ++ctx.lastSubmitted;
    list.markSubmitted(value);
    return VulkanSubmitSignal{ctx.timeline, value};
}

}  // namespace caustics::rhi
