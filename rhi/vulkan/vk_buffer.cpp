#include "vk_buffer.h"

namespace caustics::rhi::vulkan {

VkBufferUsageFlags toVkBufferUsage(BufferUsage usage) {
    // Transfers are always allowed: staging uploads and fills need them and they cost nothing.
    VkBufferUsageFlags flags = VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    if (hasAny(usage, BufferUsage::Vertex)) flags |= VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
    if (hasAny(usage, BufferUsage::Index)) flags |= VK_BUFFER_USAGE_INDEX_BUFFER_BIT;
    if (hasAny(usage, BufferUsage::Constant)) flags |= VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
    if (hasAny(usage, BufferUsage::Storage)) flags |= VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    if (hasAny(usage, BufferUsage::Indirect)) flags |= VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT;
    if (hasAny(usage, BufferUsage::AccelStructInput))
        flags |= VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    if (hasAny(usage, BufferUsage::AccelStructStorage))
        flags |= VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    if (hasAny(usage, BufferUsage::ShaderTable)) flags |= VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR;
    // Device addresses: AS inputs/storage, shader tables and storage buffers (vertex pulling through
    // buffer_reference, AS scratch), indirect arguments (vkCmdTraceRaysIndirectKHR takes an address);
    // bufferDeviceAddress is a required feature.
    if (flags & (VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR |
                 VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                 VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR))
        flags |= VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
    return flags;
}

Result<std::shared_ptr<VulkanBuffer>> VulkanBuffer::create(const ContextPtr& context, const BufferDesc& desc) {
    if (desc.byteSize == 0) return makeError("vulkan: buffer '" + desc.debugName + "' has byteSize 0");
    std::shared_ptr<VulkanBuffer> buffer(new VulkanBuffer(context, desc));
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = desc.byteSize;
    info.usage = toVkBufferUsage(desc.usage);
    const VulkanContext& ctx = *context;
    if (!ctx.capabilities.accelerationStructure)
        info.usage &= ~VkBufferUsageFlags(VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
                                          VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR);
    if (!ctx.capabilities.rayTracingPipeline) info.usage &= ~VkBufferUsageFlags(VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR);
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkResult r = ctx.fn.vkCreateBuffer(ctx.device, &info, nullptr, &buffer->buffer_);
    if (r != VK_SUCCESS) return vkError(r, "vkCreateBuffer", desc.debugName);
    ctx.setName(VK_OBJECT_TYPE_BUFFER, buffer->buffer_, desc.debugName);
    if (desc.isVirtual) return buffer;

    auto allocation = ctx.allocator->allocate(buffer->requirements(), desc.memory, false, desc.debugName);
    if (!allocation) return allocation.error();
    buffer->allocation_ = allocation.value();
    r = ctx.fn.vkBindBufferMemory(ctx.device, buffer->buffer_, buffer->allocation_.memory, buffer->allocation_.offset);
    if (r != VK_SUCCESS) return vkError(r, "vkBindBufferMemory", desc.debugName);
    buffer->mapped_ = buffer->allocation_.mapped;
    buffer->queryAddress();
    return buffer;
}

std::shared_ptr<VulkanBuffer> VulkanBuffer::wrap(const ContextPtr& context, const BufferDesc& desc, VkBuffer buffer,
                                                 uint64_t deviceAddress) {
    std::shared_ptr<VulkanBuffer> wrapped(new VulkanBuffer(context, desc));
    wrapped->buffer_ = buffer;
    wrapped->deviceAddress_ = deviceAddress;
    wrapped->ownsBuffer_ = false;
    return wrapped;
}

VulkanBuffer::~VulkanBuffer() {
    ContextPtr ctx = context_;
    VkBuffer buffer = ownsBuffer_ ? buffer_ : VK_NULL_HANDLE;
    MemoryAllocation allocation = allocation_;
    ctx->deferDestroy([ctx, buffer, allocation] {
        if (buffer != VK_NULL_HANDLE) ctx->fn.vkDestroyBuffer(ctx->device, buffer, nullptr);
        ctx->allocator->free(allocation);
    });
}

VkMemoryRequirements VulkanBuffer::requirements() const {
    VkMemoryRequirements req{};
    context_->fn.vkGetBufferMemoryRequirements(context_->device, buffer_, &req);
    return req;
}

Status VulkanBuffer::bindMemory(VkDeviceMemory memory, uint64_t offset, void* mapped) {
    VkResult r = context_->fn.vkBindBufferMemory(context_->device, buffer_, memory, offset);
    if (r != VK_SUCCESS) return vkError(r, "vkBindBufferMemory", desc_.debugName);
    mapped_ = mapped;
    queryAddress();
    return okStatus();
}

void VulkanBuffer::queryAddress() {
    if (!(toVkBufferUsage(desc_.usage) & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT)) return;
    VkBufferDeviceAddressInfo info{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
    info.buffer = buffer_;
    deviceAddress_ = context_->fn.vkGetBufferDeviceAddress(context_->device, &info);
}

}  // namespace caustics::rhi::vulkan

