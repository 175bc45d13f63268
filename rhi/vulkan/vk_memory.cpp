#include "vk_memory.h"

#include <string>

#include "vk_context.h"

namespace caustics::rhi::vulkan {
namespace {

VkMemoryPropertyFlags requiredFlags(MemoryType memory) {
    switch (memory) {
        case MemoryType::DeviceLocal: return VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
        case MemoryType::Upload: return VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
        case MemoryType::Readback: return VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    }
    return 0;
}
// Readback prefers cached memory (CPU reads of uncached memory are very slow on discrete GPUs).
VkMemoryPropertyFlags preferredFlags(MemoryType memory) {
    return memory == MemoryType::Readback ? VK_MEMORY_PROPERTY_HOST_CACHED_BIT : 0;
}

}  // namespace

Result<VkDeviceMemory> allocateDeviceMemory(VulkanContext& context, uint64_t size, uint32_t memoryType) {
    VkMemoryAllocateFlagsInfo flags{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO};
    flags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.pNext = &flags;
    info.allocationSize = size;
    info.memoryTypeIndex = memoryType;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkResult r = context.fn.vkAllocateMemory(context.device, &info, nullptr, &memory);
    if (r != VK_SUCCESS) return vkError(r, "context_.fn.vkAllocateMemory(" + std::to_string(size) + " bytes)");
    return memory;
}

MemoryAllocator::~MemoryAllocator() {
    for (Block& b : blocks_)
        if (b.memory != VK_NULL_HANDLE) context_.fn.vkFreeMemory(context_.device, b.memory, nullptr);
}

uint32_t MemoryAllocator::findMemoryType(uint32_t typeBits, MemoryType memory) const {
    const VkPhysicalDeviceMemoryProperties& props = context_.memoryProperties;
    const VkMemoryPropertyFlags required = requiredFlags(memory);
    const VkMemoryPropertyFlags preferred = required | preferredFlags(memory);
    for (VkMemoryPropertyFlags wanted : {preferred, required})
        for (uint32_t i = 0; i < props.memoryTypeCount; ++i)
            if ((typeBits & (1u << i)) && (props.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
    return UINT32_MAX;
}

Result<MemoryAllocation> MemoryAllocator::allocateDedicated(uint64_t size, uint32_t memoryType, bool hostVisible,
                                                            std::string_view debugName) {
    auto memory = allocateDeviceMemory(context_, size, memoryType);
    if (!memory) return makeError(memory.message() + " for '" + std::string(debugName) + "'");
    MemoryAllocation a;
    a.memory = memory.value();
    a.size = size;
    a.memoryType = memoryType;
    if (hostVisible) {
        VkResult r = context_.fn.vkMapMemory(context_.device, a.memory, 0, VK_WHOLE_SIZE, 0, &a.mapped);
        if (r != VK_SUCCESS) {
            context_.fn.vkFreeMemory(context_.device, a.memory, nullptr);
            return vkError(r, "vkMapMemory", debugName);
        }
    }
    return a;
}

Result<MemoryAllocation> MemoryAllocator::allocate(const VkMemoryRequirements& req, MemoryType memory, bool isImage,
                                                   std::string_view debugName) {
    const uint32_t type = findMemoryType(req.memoryTypeBits, memory);
    if (type == UINT32_MAX)
        return makeError("vulkan: no memory type fits '" + std::string(debugName) + "'");
    const bool hostVisible = memory != MemoryType::DeviceLocal;
    if (req.size > kBlockSize / 2) {
        auto dedicated = allocateDedicated(req.size, type, hostVisible, debugName);
        if (dedicated) dedicated->isImage = isImage;
        return dedicated;
    }

    std::lock_guard lock(mutex_);
    // Linear (buffers) and optimal (images) resources live in separate blocks, which satisfies
    // bufferImageGranularity without padding (Vulkan spec 12.7 "Resource Memory Association").
    auto fill = [&](int32_t index, uint64_t offset) {
        Block& b = blocks_[size_t(index)];
        MemoryAllocation a;
        a.memory = b.memory;
        a.offset = offset;
        a.size = req.size;
        a.memoryType = type;
        a.block = index;
        a.isImage = isImage;
        a.mapped = b.mapped ? static_cast<uint8_t*>(b.mapped) + offset : nullptr;
        return a;
    };
    for (size_t i = 0; i < blocks_.size(); ++i) {
        Block& b = blocks_[i];
        // Host-visible requests need a mapped block: on UMA devices (lavapipe) one memory type serves
        // DeviceLocal and Upload/Readback alike, and only blocks made for the latter are mapped.
        if (b.memory == VK_NULL_HANDLE || b.memoryType != type || b.isImage != isImage ||
            (b.mapped != nullptr) != hostVisible)
            continue;
        if (auto offset = b.ranges->allocate(req.size, req.alignment)) return fill(int32_t(i), *offset);
    }
    auto block = allocateDedicated(kBlockSize, type, hostVisible, "memory block");
    if (!block) return block.error();
    Block b;
    b.memory = block->memory;
    b.mapped = block->mapped;
    b.memoryType = type;
    b.isImage = isImage;
    b.ranges = std::make_unique<BlockAllocator>(kBlockSize);
    auto offset = b.ranges->allocate(req.size, req.alignment);
    blocks_.push_back(std::move(b));
    return fill(int32_t(blocks_.size() - 1), *offset);
}

void MemoryAllocator::free(const MemoryAllocation& a) {
    if (!a) return;
    if (a.block < 0) {
        context_.fn.vkFreeMemory(context_.device, a.memory, nullptr);   // unmapped implicitly (spec vkFreeMemory)
        return;
    }
    std::lock_guard lock(mutex_);
    Block& b = blocks_[size_t(a.block)];
    b.ranges->free(a.offset, a.size);
    // Blocks are kept once made: allocation patterns repeat every frame, re-allocating would stall.
}

}  // namespace caustics::rhi::vulkan
