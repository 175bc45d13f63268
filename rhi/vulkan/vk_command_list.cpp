// Command-list lifecycle, barriers, bindings, queries and markers.
#include "vk_command_list.h"

#include <string>

#include "vk_binding.h"
#include "vk_buffer.h"
#include "vk_device.h"
#include "vk_pipeline.h"
#include "vk_resource_state.h"
#include "vk_texture.h"
#include "vk_timestamp_pool.h"

namespace caustics::rhi::vulkan {

Result<std::shared_ptr<VulkanCommandList>> VulkanCommandList::create(VulkanDevice& device) {
    std::shared_ptr<VulkanCommandList> list(new VulkanCommandList(device.shared_from_this(), device.contextPtr()));
    const VulkanContext& ctx = *list->context_;
    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = ctx.queueFamily;
    VkResult r = ctx.fn.vkCreateCommandPool(ctx.device, &poolInfo, nullptr, &list->pool_);
    if (r != VK_SUCCESS) return vkError(r, "vkCreateCommandPool");
    VkCommandBufferAllocateInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    info.commandPool = list->pool_;
    info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    info.commandBufferCount = 1;
    r = ctx.fn.vkAllocateCommandBuffers(ctx.device, &info, &list->commandBuffer_);
    if (r != VK_SUCCESS) return vkError(r, "vkAllocateCommandBuffers");
    return list;
}

VulkanCommandList::~VulkanCommandList() {
    ContextPtr ctx = context_;
    VkCommandPool pool = pool_;
    // Transients and retained objects go with the command buffer once the GPU is done with them.
    auto transients = std::make_shared<std::vector<BufferHandle>>(std::move(transients_));
    auto retained = std::make_shared<std::vector<std::shared_ptr<const void>>>(std::move(retained_));
    ctx->deferDestroy([ctx, pool, transients, retained] {
        if (pool != VK_NULL_HANDLE) ctx->fn.vkDestroyCommandPool(ctx->device, pool, nullptr);
        transients->clear();
        retained->clear();
    });
}

void VulkanCommandList::releaseResources() {
    if (submittedFence_ > context_->completedValue()) {
        VkSemaphoreWaitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_WAIT_INFO};
        wait.semaphoreCount = 1;
        wait.pSemaphores = &context_->timeline;
        wait.pValues = &submittedFence_;
        context_->fn.vkWaitSemaphores(context_->device, &wait, UINT64_MAX);
    }
    transients_.clear();
    retained_.clear();
}

std::shared_ptr<VulkanCommandList> VulkanCommandList::wrap(VulkanDevice& device, VkCommandBuffer commandBuffer,
                                                          bool allowTimestamps) {
    std::shared_ptr<VulkanCommandList> list(new VulkanCommandList(device.shared_from_this(), device.contextPtr()));
    list->commandBuffer_ = commandBuffer;
    list->wrapped_ = true;
    list->recording_ = true;   // the host began it
    list->timestampsAllowed_ = allowTimestamps;
    return list;
}

void VulkanCommandList::begin() {
    // A wrapped list's staging buffers may still be in use by the host's last submission unless the
    // host told us when it completes (vulkanSubmitSignal); then they wait for it like ours do.
    if (!wrapped_ || submittedFence_ != 0) releaseResources();
    error_.reset();
    rayTracing_ = {};
    boundLayout_ = VK_NULL_HANDLE;
    if (wrapped_) {
        recording_ = true;
        return;
    }
    context_->fn.vkResetCommandBuffer(commandBuffer_, 0);
    VkCommandBufferBeginInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    info.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VkResult r = context_->fn.vkBeginCommandBuffer(commandBuffer_, &info);
    if (r != VK_SUCCESS) recordError(vkError(r, "vkBeginCommandBuffer").message);
    recording_ = true;
}

void VulkanCommandList::end() {
    if (wrapped_) {
        recording_ = false;
        return;
    }
    VkResult r = context_->fn.vkEndCommandBuffer(commandBuffer_);
    if (r != VK_SUCCESS) recordError(vkError(r, "vkEndCommandBuffer").message);
    recording_ = false;
}

void VulkanCommandList::recordError(std::string message) {
    log(LogLevel::Error, message);
    if (!error_) error_ = Error{std::move(message)};
}

BufferHandle VulkanCommandList::allocateTransient(const BufferDesc& desc) {
    auto buffer = device_.createBuffer(desc);
    if (!buffer) {
        recordError(buffer.message());
        return nullptr;
    }
    transients_.push_back(buffer.value());
    return buffer.value();
}

void VulkanCommandList::retain(std::shared_ptr<const void> object) { retained_.push_back(std::move(object)); }

namespace {
// Drops stages/access of features the device does not have (validation rejects them).
void maskUnsupported(const Capabilities& caps, VkStateInfo& s) {
    if (!caps.rayTracingPipeline) {
        s.stages &= ~VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR;
        s.access &= ~VK_ACCESS_2_SHADER_BINDING_TABLE_READ_BIT_KHR;
    }
    if (!caps.accelerationStructure) {
        s.stages &= ~VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR;
        s.access &= ~(VK_ACCESS_2_ACCELERATION_STRUCTURE_READ_BIT_KHR | VK_ACCESS_2_ACCELERATION_STRUCTURE_WRITE_BIT_KHR);
    }
    if (s.stages == 0) s.stages = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
}

// Source and destination scopes of an image or buffer barrier. An aliasing barrier (memory another
// resource used before, or an earlier frame) waits for every stage of the work that used that memory
// (`beforeStages`; all commands when not said), like D3D12's aliasing barrier; the render graph asks for it.
template <typename Barrier>
void setStagesAndAccess(const Capabilities& caps, Barrier& barrier, const VkStateInfo& src, const VkStateInfo& dst,
                        bool aliasing, PipelineStages beforeStages) {
    VkStateInfo earlierUse{stagesOfWork(beforeStages), VK_ACCESS_2_MEMORY_WRITE_BIT};
    maskUnsupported(caps, earlierUse);
    barrier.srcStageMask = aliasing ? earlierUse.stages : src.stages;
    barrier.srcAccessMask = aliasing ? earlierUse.access : src.access;
    barrier.dstStageMask = dst.stages;
    barrier.dstAccessMask = dst.access;
}
}  // namespace

void VulkanCommandList::barriers(std::span<const TextureBarrier> textures, std::span<const BufferBarrier> buffers,
                                 std::span<const AccelStructBarrier> accelStructs) {
    const Capabilities& caps = context_->capabilities;
    std::vector<VkImageMemoryBarrier2> images;
    std::vector<VkBufferMemoryBarrier2> bufs;
    std::vector<VkMemoryBarrier2> memory;
    for (const TextureBarrier& b : textures) {
        VulkanTexture* t = toVk(b.texture);
        if (!t) continue;
        const bool depth = formatInfo(t->desc().format).isDepth;
        VkStateInfo src = translateState(b.before, depth, b.beforeStages);
        VkStateInfo dst = translateState(b.after, depth, b.afterStages);
        maskUnsupported(caps, src);
        maskUnsupported(caps, dst);
        VkImageMemoryBarrier2 ib{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
        setStagesAndAccess(caps, ib, src, dst, b.aliasing, b.beforeStages);
        ib.oldLayout = b.before == ResourceState::Undefined ? VK_IMAGE_LAYOUT_UNDEFINED : src.layout;
        ib.newLayout = dst.layout;
        ib.srcQueueFamilyIndex = ib.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        ib.image = t->handle();
        const TextureSubresources& s = b.subresources;
        ib.subresourceRange = {t->aspect(), s.baseMip, s.mipCount == ~0u ? VK_REMAINING_MIP_LEVELS : s.mipCount,
                               s.baseLayer, s.layerCount == ~0u ? VK_REMAINING_ARRAY_LAYERS : s.layerCount};
        images.push_back(ib);
    }
    for (const BufferBarrier& b : buffers) {
        VulkanBuffer* buf = toVk(b.buffer);
        if (!buf) continue;
        VkStateInfo src = translateState(b.before, false, b.beforeStages);
        VkStateInfo dst = translateState(b.after, false, b.afterStages);
        maskUnsupported(caps, src);
        maskUnsupported(caps, dst);
        VkBufferMemoryBarrier2 bb{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
        setStagesAndAccess(caps, bb, src, dst, b.aliasing, b.beforeStages);
        bb.srcQueueFamilyIndex = bb.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        bb.buffer = buf->handle();
        bb.offset = 0;
        bb.size = VK_WHOLE_SIZE;
        bufs.push_back(bb);
    }
    // Acceleration structures are ordered with a global memory barrier (the AS is not a buffer the
    // RHI exposes; VK_KHR_acceleration_structure "Acceleration Structure Synchronization").
    for (const AccelStructBarrier& b : accelStructs) {
        VkStateInfo src = translateState(b.before, false, b.beforeStages);
        VkStateInfo dst = translateState(b.after, false, b.afterStages);
        maskUnsupported(caps, src);
        maskUnsupported(caps, dst);
        VkMemoryBarrier2 mb{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
        mb.srcStageMask = src.stages;
        mb.srcAccessMask = src.access;
        mb.dstStageMask = dst.stages;
        mb.dstAccessMask = dst.access;
        memory.push_back(mb);
    }
    if (images.empty() && bufs.empty() && memory.empty()) return;
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.memoryBarrierCount = uint32_t(memory.size());
    dep.pMemoryBarriers = memory.data();
    dep.bufferMemoryBarrierCount = uint32_t(bufs.size());
    dep.pBufferMemoryBarriers = bufs.data();
    dep.imageMemoryBarrierCount = uint32_t(images.size());
    dep.pImageMemoryBarriers = images.data();
    context_->fn.vkCmdPipelineBarrier2(commandBuffer_, &dep);
}

void VulkanCommandList::setComputePipeline(const ComputePipelineHandle& pipeline) {
    VulkanComputePipeline* p = toVk(pipeline);
    context_->fn.vkCmdBindPipeline(commandBuffer_, VK_PIPELINE_BIND_POINT_COMPUTE, p->pipeline());
    bindPipelineLayout(p->layout(), VK_PIPELINE_BIND_POINT_COMPUTE);
    retain(pipeline);
}

void VulkanCommandList::dispatch(uint32_t x, uint32_t y, uint32_t z) { context_->fn.vkCmdDispatch(commandBuffer_, x, y, z); }

void VulkanCommandList::dispatchIndirect(const BufferHandle& args, uint64_t offset) {
    VulkanBuffer* buf = toVk(args);
    if (!buf || !hasAny(args->desc().usage, BufferUsage::Indirect) || offset % 4 != 0 ||
        offset + 12 > args->desc().byteSize) {
        recordError("dispatchIndirect: the argument buffer needs BufferUsage::Indirect and 12 bytes at a 4-aligned offset");
        return;
    }
    retain(args);
    context_->fn.vkCmdDispatchIndirect(commandBuffer_, buf->handle(), offset);
}

void VulkanCommandList::setBindingSet(uint32_t index, const BindingSetHandle& set) {
    if (boundLayout_ == VK_NULL_HANDLE) {
        recordError("vulkan: setBindingSet before any pipeline was set");
        return;
    }
    VkDescriptorSet s = toVk(set)->handle();
    context_->fn.vkCmdBindDescriptorSets(commandBuffer_, boundBindPoint_, boundLayout_, index, 1, &s, 0, nullptr);
    retain(set);
}

void VulkanCommandList::setPushConstants(const void* data, uint32_t bytes) {
    if (boundLayout_ == VK_NULL_HANDLE) {
        recordError("vulkan: setPushConstants before any pipeline was set");
        return;
    }
    context_->fn.vkCmdPushConstants(commandBuffer_, boundLayout_, VK_SHADER_STAGE_ALL, 0, bytes, data);
}

void VulkanCommandList::resetTimestamps(const TimestampPoolHandle& pool, uint32_t first, uint32_t count) {
    if (!timestampsAllowed_) return;
    context_->fn.vkCmdResetQueryPool(commandBuffer_, toVk(pool)->handle(), first, count);
    retain(pool);
}

void VulkanCommandList::writeTimestamp(const TimestampPoolHandle& pool, uint32_t index) {
    if (!timestampsAllowed_) return;
    context_->fn.vkCmdWriteTimestamp2(commandBuffer_, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, toVk(pool)->handle(), index);
    retain(pool);
}

void VulkanCommandList::beginMarker(std::string_view name) {
    if (!context_->fn.vkCmdBeginDebugUtilsLabelEXT) return;
    std::string terminated(name);
    VkDebugUtilsLabelEXT label{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT};
    label.pLabelName = terminated.c_str();
    context_->fn.vkCmdBeginDebugUtilsLabelEXT(commandBuffer_, &label);
}

void VulkanCommandList::endMarker() {
    if (context_->fn.vkCmdEndDebugUtilsLabelEXT) context_->fn.vkCmdEndDebugUtilsLabelEXT(commandBuffer_);
}

}  // namespace caustics::rhi::vulkan
