// Submission with a timeline semaphore as the device fence, waits, readbacks and timestamps.
#include <cstring>
#include <string>

#include "vk_buffer.h"
#include "vk_device.h"
#include "vk_timestamp_pool.h"

namespace caustics::rhi::vulkan {

Result<uint64_t> VulkanDevice::submit(std::span<const CommandListHandle> lists) {
    std::vector<VkCommandBufferSubmitInfo> buffers;
    for (const CommandListHandle& handle : lists) {
        VulkanCommandList* list = toVk(handle);
        if (list->isWrapped())
            return makeError("vulkan: submit of a wrapped host command buffer; the host submits it itself");
        if (list->isRecording()) return makeError("vulkan: submit of a command list that was not end()ed");
        if (list->recordingError()) return list->recordingError().value();
        VkCommandBufferSubmitInfo b{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
        b.commandBuffer = list->commandBuffer();
        buffers.push_back(b);
    }
    const uint64_t value = context_->lastSubmitted + 1;
    VkSemaphoreSubmitInfo signal{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    signal.semaphore = context_->timeline;
    signal.value = value;
    signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    VkSubmitInfo2 info{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    info.commandBufferInfoCount = uint32_t(buffers.size());
    info.pCommandBufferInfos = buffers.data();
    info.signalSemaphoreInfoCount = 1;
    info.pSignalSemaphoreInfos = &signal;
    VkResult r = context_->fn.vkQueueSubmit2(context_->queue, 1, &info, VK_NULL_HANDLE);
    if (r != VK_SUCCESS) return vkError(r, "vkQueueSubmit2");
    context_->lastSubmitted = value;
    for (const CommandListHandle& handle : lists) toVk(handle)->markSubmitted(value);
    context_->collectGarbage();
    return value;
}

Status VulkanDevice::waitForFence(uint64_t value) {
    if (value > context_->lastSubmitted)
        return makeError("vulkan: waitForFence(" + std::to_string(value) + ") on a value never submitted");
    VkSemaphoreWaitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_WAIT_INFO};
    wait.semaphoreCount = 1;
    wait.pSemaphores = &context_->timeline;
    wait.pValues = &value;
    VkResult r = context_->fn.vkWaitSemaphores(context_->device, &wait, UINT64_MAX);
    if (r != VK_SUCCESS) return vkError(r, "vkWaitSemaphores");
    context_->collectGarbage();
    return okStatus();
}

Status VulkanDevice::waitIdle() {
    VkResult r = context_->fn.vkQueueWaitIdle(context_->queue);
    if (r != VK_SUCCESS) return vkError(r, "vkQueueWaitIdle");
    context_->collectGarbage();
    return okStatus();
}

Status VulkanDevice::readBuffer(const BufferHandle& buffer, void* dst, uint64_t bytes, uint64_t offset) {
    IBuffer* b = buffer.get();
    if (!b || !b->mappedData())
        return makeError("vulkan: readBuffer needs a host-visible (Upload/Readback) buffer");
    if (offset + bytes > b->desc().byteSize)
        return makeError("vulkan: readBuffer past the end of '" + b->desc().debugName + "'");
    // Host-coherent memory: visible once the submission's fence completed (spec 7.9 host access).
    std::memcpy(dst, static_cast<const uint8_t*>(b->mappedData()) + offset, bytes);
    return okStatus();
}

std::vector<std::optional<double>> VulkanDevice::readTimestamps(const TimestampPoolHandle& pool, uint32_t first,
                                                                uint32_t count) {
    std::vector<std::optional<double>> out(count);
    if (count == 0) return out;
    std::vector<uint64_t> data(size_t(count) * 2);   // (value, availability) pairs
    context_->fn.vkGetQueryPoolResults(context_->device, toVk(pool)->handle(), first, count, data.size() * sizeof(uint64_t),
                          data.data(), 2 * sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WITH_AVAILABILITY_BIT);
    for (uint32_t i = 0; i < count; ++i)
        if (data[2 * i + 1] != 0) out[i] = double(data[2 * i]) * context_->capabilities.timestampPeriodNs;
    return out;
}

Status VulkanDevice::executeImmediate(const std::function<void(VulkanCommandList&)>& record) {
    auto list = createCommandList();
    if (!list) return list.error();
    VulkanCommandList& vk = *toVk(list.value());
    vk.begin();
    record(vk);
    vk.end();
    auto fence = submit(list.value());
    if (!fence) return fence.error();
    return waitForFence(fence.value());
}

}  // namespace caustics::rhi::vulkan
