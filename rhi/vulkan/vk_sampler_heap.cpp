// Samplers and memory heaps (small objects of vk_texture.h).
#include "vk_texture.h"

namespace caustics::rhi::vulkan {
namespace {
VkSamplerAddressMode toVkAddress(AddressMode mode) {
    switch (mode) {
        case AddressMode::Repeat: return VK_SAMPLER_ADDRESS_MODE_REPEAT;
        case AddressMode::ClampToEdge: return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        case AddressMode::MirroredRepeat: return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
    }
    return VK_SAMPLER_ADDRESS_MODE_REPEAT;
}
}  // namespace

Result<std::shared_ptr<VulkanSampler>> VulkanSampler::create(const ContextPtr& context, const SamplerDesc& desc) {
    std::shared_ptr<VulkanSampler> sampler(new VulkanSampler(context, desc));
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    const VkFilter filter = desc.filter == FilterMode::Linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
    info.magFilter = info.minFilter = filter;
    info.mipmapMode = desc.filter == FilterMode::Linear ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.addressModeU = info.addressModeV = info.addressModeW = toVkAddress(desc.address);
    // Anisotropy is an optional feature we do not enable; the request is clamped to none.
    info.anisotropyEnable = VK_FALSE;
    info.maxAnisotropy = 1.0f;
    info.maxLod = VK_LOD_CLAMP_NONE;
    VkResult r = context->fn.vkCreateSampler(context->device, &info, nullptr, &sampler->sampler_);
    if (r != VK_SUCCESS) return vkError(r, "vkCreateSampler");
    return sampler;
}

VulkanSampler::~VulkanSampler() {
    ContextPtr ctx = context_;
    VkSampler s = sampler_;
    ctx->deferDestroy([ctx, s] { ctx->fn.vkDestroySampler(ctx->device, s, nullptr); });
}

Result<std::shared_ptr<VulkanHeap>> VulkanHeap::create(const ContextPtr& context, const HeapDesc& desc) {
    if (desc.byteSize == 0) return makeError("vulkan: heap '" + desc.debugName + "' has byteSize 0");
    std::shared_ptr<VulkanHeap> heap(new VulkanHeap(context, desc));
    heap->memoryType_ = context->allocator->findMemoryType(~0u, MemoryType::DeviceLocal);
    if (heap->memoryType_ == UINT32_MAX) return makeError("vulkan: no device-local memory type for heap");
    auto memory = allocateDeviceMemory(*context, desc.byteSize, heap->memoryType_);
    if (!memory) return makeError(memory.message() + " for heap '" + desc.debugName + "'");
    heap->memory_ = memory.value();
    context->setName(VK_OBJECT_TYPE_DEVICE_MEMORY, heap->memory_, desc.debugName);
    return heap;
}

VulkanHeap::~VulkanHeap() {
    ContextPtr ctx = context_;
    VkDeviceMemory m = memory_;
    ctx->deferDestroy([ctx, m] { ctx->fn.vkFreeMemory(ctx->device, m, nullptr); });
}

}  // namespace caustics::rhi::vulkan
