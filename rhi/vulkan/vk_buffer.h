#pragma once
// Buffers: a VkBuffer with sub-allocated memory (or, when virtual, memory bound later from a heap).
#include <vulkan/vulkan.h>

#include "caustics/rhi/resources.h"
#include "vk_context.h"
#include "vk_memory.h"

namespace caustics::rhi::vulkan {

VkBufferUsageFlags toVkBufferUsage(BufferUsage usage);

class VulkanBuffer final : public IBuffer {
public:
    // Creates the VkBuffer and, unless desc.isVirtual, its memory.
    static Result<std::shared_ptr<VulkanBuffer>> create(const ContextPtr& context, const BufferDesc& desc);
    // A host engine's buffer (vk_interop_resources.cpp): never destroyed here.
    static std::shared_ptr<VulkanBuffer> wrap(const ContextPtr& context, const BufferDesc& desc, VkBuffer buffer,
                                              uint64_t deviceAddress);
    ~VulkanBuffer() override;

    const BufferDesc& desc() const override { return desc_; }
    NativeObject getNativeObject(NativeObjectType type) const override {
        return type == NativeObjectType::VkBuffer ? NativeObject::from(buffer_) : NativeObject();
    }
    uint64_t deviceAddress() const override { return deviceAddress_; }
    void* mappedData() override { return mapped_; }

    VkBuffer handle() const { return buffer_; }
    VkMemoryRequirements requirements() const;
    // Binds a virtual buffer to external memory (a heap); `mapped` is the heap's host pointer or null.
    Status bindMemory(VkDeviceMemory memory, uint64_t offset, void* mapped);

private:
    VulkanBuffer(ContextPtr context, const BufferDesc& desc) : context_(std::move(context)), desc_(desc) {}
    void queryAddress();

    ContextPtr context_;
    BufferDesc desc_;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    bool ownsBuffer_ = true;
    MemoryAllocation allocation_;   // empty for virtual buffers
    uint64_t deviceAddress_ = 0;
    void* mapped_ = nullptr;
};

// Downcasts an rhi handle; null for a null handle. Every IBuffer of a Vulkan device is a VulkanBuffer.
inline VulkanBuffer* toVk(const BufferHandle& buffer) { return static_cast<VulkanBuffer*>(buffer.get()); }

}  // namespace caustics::rhi::vulkan
