#pragma once
// Device-free bookkeeping of one memory block: first-fit over a sorted free list, coalescing on free.
// The Vulkan allocator (vk_memory.h) keeps one of these per VkDeviceMemory block; unit-tested in
// tests/unit/rhi/block_allocator_test.cpp.
#include <cstdint>
#include <map>
#include <optional>

namespace caustics::rhi::vulkan {

class BlockAllocator {
public:
    explicit BlockAllocator(uint64_t capacity);

    // Offset of a new range of `size` bytes aligned to `alignment` (a power of two), or nullopt if
    // no free range fits. Padding in front of the aligned start stays free.
    std::optional<uint64_t> allocate(uint64_t size, uint64_t alignment);
    // Returns a range previously allocated; merges it with free neighbours.
    void free(uint64_t offset, uint64_t size);

    uint64_t capacity() const { return capacity_; }
    uint64_t usedBytes() const { return used_; }
    bool empty() const { return used_ == 0; }
    size_t freeRangeCount() const { return free_.size(); }

private:
    uint64_t capacity_;
    uint64_t used_ = 0;
    std::map<uint64_t, uint64_t> free_;   // offset -> size, never adjacent (always coalesced)
};

}  // namespace caustics::rhi::vulkan
