#pragma once
// GPU memory: large blocks per (memory type, linear/optimal) sub-allocated with BlockAllocator, and
// dedicated allocations for resources larger than a block. Vulkan Memory Allocator is not packaged in
// Debian 12, hence this small allocator.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "caustics/rhi/resources.h"
#include "caustics/rhi/result.h"
#include "vk_block_allocator.h"

namespace caustics::rhi::vulkan {

struct VulkanContext;

struct MemoryAllocation {
    VkDeviceMemory memory = VK_NULL_HANDLE;
    uint64_t offset = 0;
    uint64_t size = 0;
    void* mapped = nullptr;      // host pointer at `offset` for host-visible memory
    uint32_t memoryType = 0;
    int32_t block = -1;          // -1 = dedicated
    bool isImage = false;
    explicit operator bool() const { return memory != VK_NULL_HANDLE; }
};

class MemoryAllocator {
public:
    static constexpr uint64_t kBlockSize = 64ull << 20;

    explicit MemoryAllocator(VulkanContext& context) : context_(context) {}
    ~MemoryAllocator();

    Result<MemoryAllocation> allocate(const VkMemoryRequirements& requirements, MemoryType memory, bool isImage,
                                      std::string_view debugName);
    void free(const MemoryAllocation& allocation);

    // Index of a memory type allowed by `typeBits` with the properties `memory` needs; UINT32_MAX if none.
    uint32_t findMemoryType(uint32_t typeBits, MemoryType memory) const;

private:
    struct Block {
        VkDeviceMemory memory = VK_NULL_HANDLE;
        void* mapped = nullptr;
        uint32_t memoryType = 0;
        bool isImage = false;
        std::unique_ptr<BlockAllocator> ranges;
    };
    Result<MemoryAllocation> allocateDedicated(uint64_t size, uint32_t memoryType, bool hostVisible,
                                               std::string_view debugName);

    VulkanContext& context_;
    std::mutex mutex_;
    std::vector<Block> blocks_;
};

// Allocates device memory without sub-allocation (heaps, dedicated resources). Every allocation carries
// VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT so buffers placed in it may use their device address.
Result<VkDeviceMemory> allocateDeviceMemory(VulkanContext& context, uint64_t size, uint32_t memoryType);

}  // namespace caustics::rhi::vulkan
