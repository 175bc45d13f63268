#pragma once
// Textures (2D, 2D arrays, cubes, depth) with their views, samplers and memory heaps.
#include <vulkan/vulkan.h>

#include <map>
#include <mutex>

#include "caustics/rhi/resources.h"
#include "vk_context.h"
#include "vk_memory.h"

namespace caustics::rhi::vulkan {

VkFormat toVkFormat(Format format);
VkImageAspectFlags aspectOf(Format format);

class VulkanTexture final : public ITexture {
public:
    static Result<std::shared_ptr<VulkanTexture>> create(const ContextPtr& context, const TextureDesc& desc);
    // A host engine's image (vk_interop_resources.cpp): never destroyed here; only our views are.
    static std::shared_ptr<VulkanTexture> wrap(const ContextPtr& context, const TextureDesc& desc, VkImage image,
                                               VkFormat format);
    ~VulkanTexture() override;

    const TextureDesc& desc() const override { return desc_; }
    NativeObject getNativeObject(NativeObjectType type) const override {
        return type == NativeObjectType::VkImage ? NativeObject::from(image_) : NativeObject();
    }

    VkImage handle() const { return image_; }
    VkFormat format() const { return format_; }
    VkImageAspectFlags aspect() const { return aspectOf(desc_.format); }
    VkMemoryRequirements requirements() const;
    Status bindMemory(VkDeviceMemory memory, uint64_t offset);

    // View of every layer and mip, typed by the dimension (2D, 2D array, cube): for sampling.
    VkImageView sampledView();
    // View for storage images: cubes are seen as 2D arrays of 6 layers (GLSL image2DArray).
    VkImageView storageView();
    // Single-layer, single-mip 2D view: render/depth attachments.
    VkImageView layerView(uint32_t layer, uint32_t mip = 0);

private:
    VulkanTexture(ContextPtr context, const TextureDesc& desc) : context_(std::move(context)), desc_(desc) {}
    Result<VkImageView> makeView(VkImageViewType type, uint32_t baseLayer, uint32_t layers, uint32_t baseMip,
                                 uint32_t mips);

    ContextPtr context_;
    TextureDesc desc_;
    VkImage image_ = VK_NULL_HANDLE;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    bool ownsImage_ = true;
    MemoryAllocation allocation_;
    std::mutex viewMutex_;
    std::map<uint64_t, VkImageView> views_;   // key: (kind << 48) | (layer << 16) | mip
};

inline VulkanTexture* toVk(const TextureHandle& texture) { return static_cast<VulkanTexture*>(texture.get()); }

class VulkanSampler final : public ISampler {
public:
    static Result<std::shared_ptr<VulkanSampler>> create(const ContextPtr& context, const SamplerDesc& desc);
    ~VulkanSampler() override;
    const SamplerDesc& desc() const override { return desc_; }
    VkSampler handle() const { return sampler_; }

private:
    VulkanSampler(ContextPtr context, const SamplerDesc& desc) : context_(std::move(context)), desc_(desc) {}
    ContextPtr context_;
    SamplerDesc desc_;
    VkSampler sampler_ = VK_NULL_HANDLE;
};

inline VulkanSampler* toVk(const SamplerHandle& sampler) { return static_cast<VulkanSampler*>(sampler.get()); }

// One VkDeviceMemory into which virtual resources are placed (device-local).
class VulkanHeap final : public IHeap {
public:
    static Result<std::shared_ptr<VulkanHeap>> create(const ContextPtr& context, const HeapDesc& desc);
    ~VulkanHeap() override;
    const HeapDesc& desc() const override { return desc_; }
    VkDeviceMemory memory() const { return memory_; }
    uint32_t memoryType() const { return memoryType_; }

private:
    VulkanHeap(ContextPtr context, const HeapDesc& desc) : context_(std::move(context)), desc_(desc) {}
    ContextPtr context_;
    HeapDesc desc_;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    uint32_t memoryType_ = 0;
};

inline VulkanHeap* toVk(const HeapHandle& heap) { return static_cast<VulkanHeap*>(heap.get()); }

}  // namespace caustics::rhi::vulkan
