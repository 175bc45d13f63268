#include "vk_block_allocator.h"

#include <cassert>
#include <iterator>

namespace caustics::rhi::vulkan {

BlockAllocator::BlockAllocator(uint64_t capacity) : capacity_(capacity) {
    if (capacity > 0) free_.emplace(0, capacity);
}

std::optional<uint64_t> BlockAllocator::allocate(uint64_t size, uint64_t alignment) {
    if (size == 0) size = 1;
    if (alignment == 0) alignment = 1;
    for (auto it = free_.begin(); it != free_.end(); ++it) {
        const uint64_t start = it->first;
        const uint64_t rangeSize = it->second;
        const uint64_t aligned = (start + alignment - 1) & ~(alignment - 1);
        const uint64_t padding = aligned - start;
        if (padding + size > rangeSize) continue;
        // Split [start, start+rangeSize) into padding (stays free), the allocation, and the tail.
        const uint64_t tail = rangeSize - padding - size;
        free_.erase(it);
        if (padding > 0) free_.emplace(start, padding);
        if (tail > 0) free_.emplace(aligned + size, tail);
        used_ += size;
        return aligned;
    }
    return std::nullopt;
}

void BlockAllocator::free(uint64_t offset, uint64_t size) {
    if (size == 0) size = 1;
    assert(offset + size <= capacity_);
    used_ -= size;
    auto next = free_.lower_bound(offset);
    assert(next == free_.end() || next->first >= offset + size);
    uint64_t start = offset;
    uint64_t length = size;
    // Merge with the free range just before, if it ends where this one starts.
    if (next != free_.begin()) {
        auto prev = std::prev(next);
        assert(prev->first + prev->second <= offset);
        if (prev->first + prev->second == offset) {
            start = prev->first;
            length += prev->second;
            free_.erase(prev);
        }
    }
    // And with the one just after.
    if (next != free_.end() && next->first == offset + size) {
        length += next->second;
        free_.erase(next);
    }
    free_.emplace(start, length);
}

}  // namespace caustics::rhi::vulkan
