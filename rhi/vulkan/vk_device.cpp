// VulkanDevice: creation, object factories and memory placement.
#include "vk_device.h"

#include <algorithm>

#include <string>

#include "vk_binding.h"
#include "vk_buffer.h"
#include "vk_instance.h"
#include "vk_memory.h"
#include "vk_pipeline.h"
#include "vk_texture.h"
#include "vk_timestamp_pool.h"

namespace caustics::rhi::vulkan {

Result<std::shared_ptr<VulkanDevice>> VulkanDevice::create(const DeviceDesc& desc) {
    auto context = std::make_shared<VulkanContext>();
    context->validationCallback = desc.validationCallback;
    CAUSTICS_CHECK(createInstance(*context, desc));
    CAUSTICS_CHECK(createLogicalDevice(*context, desc));
    context->allocator = std::make_unique<MemoryAllocator>(*context);
    context->descriptors = std::make_unique<DescriptorAllocator>(*context);
    log(LogLevel::Info, "vulkan: using '" + context->capabilities.adapterName + "' (" +
                            context->capabilities.driverName + ")");
    return std::shared_ptr<VulkanDevice>(new VulkanDevice(std::move(context)));
}

VulkanDevice::~VulkanDevice() {
    // The context (and VkDevice) lives on while objects hold it; make sure nothing is in flight.
    if (context_) context_->waitForKnownWork();
    if (context_) context_->collectGarbage(true);
}

NativeObject VulkanDevice::getNativeObject(NativeObjectType type) const {
    switch (type) {
        case NativeObjectType::VkInstance: return NativeObject::from(context_->instance);
        case NativeObjectType::VkPhysicalDevice: return NativeObject::from(context_->physicalDevice);
        case NativeObjectType::VkDevice: return NativeObject::from(context_->device);
        case NativeObjectType::VkQueue: return NativeObject::from(context_->queue);
        default: return {};
    }
}

Result<BufferHandle> VulkanDevice::createBuffer(const BufferDesc& desc) {
    auto b = VulkanBuffer::create(context_, desc);
    if (!b) return b.error();
    return BufferHandle(b.value());
}

Result<TextureHandle> VulkanDevice::createTexture(const TextureDesc& desc) {
    auto t = VulkanTexture::create(context_, desc);
    if (!t) return t.error();
    return TextureHandle(t.value());
}

Result<SamplerHandle> VulkanDevice::createSampler(const SamplerDesc& desc) {
    auto s = VulkanSampler::create(context_, desc);
    if (!s) return s.error();
    return SamplerHandle(s.value());
}

Result<HeapHandle> VulkanDevice::createHeap(const HeapDesc& desc) {
    auto h = VulkanHeap::create(context_, desc);
    if (!h) return h.error();
    return HeapHandle(h.value());
}

namespace {
// What a virtual resource needs of a heap that also holds resources of the other tiling (the render
// graph aliases buffers and optimal images in one heap): start and end on bufferImageGranularity
// pages, so that no linear and optimal resource share one (Vulkan spec 12.7 "Resource Memory
// Association"). The device's own limit, not a guess: 1 on many desktop GPUs, 64 on lavapipe.
MemoryRequirements placedRequirements(const VkMemoryRequirements& r, const VulkanContext& context) {
    const uint64_t page = std::max<uint64_t>(1, context.properties.limits.bufferImageGranularity);
    const uint64_t alignment = std::max<uint64_t>(r.alignment, page);
    return {(r.size + page - 1) / page * page, alignment};
}
}  // namespace

MemoryRequirements VulkanDevice::memoryRequirements(const TextureDesc& desc) {
    TextureDesc probe = desc;
    probe.isVirtual = true;
    auto t = VulkanTexture::create(context_, probe);
    if (!t) return {};
    return placedRequirements(t.value()->requirements(), *context_);
}

MemoryRequirements VulkanDevice::memoryRequirements(const BufferDesc& desc) {
    BufferDesc probe = desc;
    probe.isVirtual = true;
    auto b = VulkanBuffer::create(context_, probe);
    if (!b) return {};
    return placedRequirements(b.value()->requirements(), *context_);
}

namespace {
Status checkPlacement(const VkMemoryRequirements& req, const VulkanHeap& heap, uint64_t offset, bool isVirtual,
                      const std::string& name) {
    if (!isVirtual) return makeError("vulkan: bindMemory of '" + name + "', which is not virtual");
    if (offset % req.alignment != 0)
        return makeError("vulkan: bindMemory of '" + name + "' at offset " + std::to_string(offset) +
                         " not aligned to " + std::to_string(req.alignment));
    if (offset + req.size > heap.desc().byteSize)
        return makeError("vulkan: '" + name + "' (" + std::to_string(req.size) + " bytes at " + std::to_string(offset) +
                         ") does not fit heap '" + heap.desc().debugName + "'");
    if (!(req.memoryTypeBits & (1u << heap.memoryType())))
        return makeError("vulkan: '" + name + "' cannot live in the memory type of heap '" + heap.desc().debugName + "'");
    return okStatus();
}
}  // namespace

Status VulkanDevice::bindMemory(const TextureHandle& texture, const HeapHandle& heap, uint64_t offset) {
    VulkanTexture* t = toVk(texture);
    VulkanHeap* h = toVk(heap);
    CAUSTICS_CHECK(checkPlacement(t->requirements(), *h, offset, t->desc().isVirtual, t->desc().debugName));
    return t->bindMemory(h->memory(), offset);
}

Status VulkanDevice::bindMemory(const BufferHandle& buffer, const HeapHandle& heap, uint64_t offset) {
    VulkanBuffer* b = toVk(buffer);
    VulkanHeap* h = toVk(heap);
    if (b->desc().memory != MemoryType::DeviceLocal)
        return makeError("vulkan: heaps are device-local; '" + b->desc().debugName + "' wants host memory");
    CAUSTICS_CHECK(checkPlacement(b->requirements(), *h, offset, b->desc().isVirtual, b->desc().debugName));
    return b->bindMemory(h->memory(), offset, nullptr);
}

Result<BindingLayoutHandle> VulkanDevice::createBindingLayout(const BindingLayoutDesc& desc) {
    auto l = VulkanBindingLayout::create(context_, desc);
    if (!l) return l.error();
    return BindingLayoutHandle(l.value());
}

Result<BindingSetHandle> VulkanDevice::createBindingSet(const BindingSetDesc& desc, const BindingLayoutHandle& layout) {
    auto s = VulkanBindingSet::create(context_, desc, layout);
    if (!s) return s.error();
    return BindingSetHandle(s.value());
}

Result<ComputePipelineHandle> VulkanDevice::createComputePipeline(const ComputePipelineDesc& desc) {
    auto p = VulkanComputePipeline::create(context_, desc);
    if (!p) return p.error();
    return ComputePipelineHandle(p.value());
}

Result<GraphicsPipelineHandle> VulkanDevice::createGraphicsPipeline(const GraphicsPipelineDesc& desc) {
    auto p = VulkanGraphicsPipeline::create(context_, desc);
    if (!p) return p.error();
    return GraphicsPipelineHandle(p.value());
}

Result<TimestampPoolHandle> VulkanDevice::createTimestampPool(uint32_t count) {
    auto p = VulkanTimestampPool::create(context_, count);
    if (!p) return p.error();
    return TimestampPoolHandle(p.value());
}

Result<CommandListHandle> VulkanDevice::createCommandList() {
    auto c = VulkanCommandList::create(*this);
    if (!c) return c.error();
    return CommandListHandle(c.value());
}

}  // namespace caustics::rhi::vulkan
