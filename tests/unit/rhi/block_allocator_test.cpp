#include "vk_block_allocator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace caustics::rhi::vulkan {
namespace {

TEST(BlockAllocator, AllocatesFromTheStartFirstFit) {
    BlockAllocator a(1024);
    EXPECT_EQ(a.allocate(100, 1), 0u);
    EXPECT_EQ(a.allocate(100, 1), 100u);
    EXPECT_EQ(a.usedBytes(), 200u);
}

TEST(BlockAllocator, HonoursAlignment) {
    BlockAllocator a(4096);
    ASSERT_EQ(a.allocate(3, 1), 0u);
    auto aligned = a.allocate(64, 256);
    ASSERT_TRUE(aligned);
    EXPECT_EQ(*aligned % 256, 0u);
    EXPECT_EQ(*aligned, 256u);
    // The padding in front of the aligned range stays usable.
    EXPECT_EQ(a.allocate(8, 1), 3u);
}

TEST(BlockAllocator, RefusesWhatDoesNotFit) {
    BlockAllocator a(256);
    EXPECT_FALSE(a.allocate(257, 1));
    ASSERT_TRUE(a.allocate(200, 1));
    EXPECT_FALSE(a.allocate(100, 1));
}

TEST(BlockAllocator, FreeingNeighboursCoalescesIntoOneRange) {
    BlockAllocator a(300);
    auto x = a.allocate(100, 1), y = a.allocate(100, 1), z = a.allocate(100, 1);
    ASSERT_TRUE(x && y && z);
    a.free(*x, 100);
    a.free(*z, 100);
    EXPECT_EQ(a.freeRangeCount(), 2u);
    a.free(*y, 100);   // joins both neighbours
    EXPECT_EQ(a.freeRangeCount(), 1u);
    EXPECT_TRUE(a.empty());
    EXPECT_EQ(a.allocate(300, 1), 0u);   // the whole block is one range again
}

TEST(BlockAllocator, RandomizedLiveRangesNeverOverlapAndAllFreeRestoresTheBlock) {
    constexpr uint64_t kCapacity = 1 << 20;
    BlockAllocator a(kCapacity);
    std::mt19937 rng(1234);
    struct Range { uint64_t offset, size; };
    std::vector<Range> live;
    for (int step = 0; step < 5000; ++step) {
        if (live.empty() || rng() % 3 != 0) {
            const uint64_t size = 1 + rng() % 8192;
            const uint64_t alignment = uint64_t(1) << (rng() % 9);
            if (auto offset = a.allocate(size, alignment)) {
                ASSERT_EQ(*offset % alignment, 0u);
                ASSERT_LE(*offset + size, kCapacity);
                live.push_back({*offset, size});
            }
        } else {
            const size_t i = rng() % live.size();
            a.free(live[i].offset, live[i].size);
            live[i] = live.back();
            live.pop_back();
        }
        if (step % 100 == 0) {
            std::vector<Range> sorted = live;
            std::sort(sorted.begin(), sorted.end(), [](const Range& l, const Range& r) { return l.offset < r.offset; });
            for (size_t i = 1; i < sorted.size(); ++i)
                ASSERT_LE(sorted[i - 1].offset + sorted[i - 1].size, sorted[i].offset) << "overlap at step " << step;
        }
    }
    for (const Range& r : live) a.free(r.offset, r.size);
    EXPECT_TRUE(a.empty());
    EXPECT_EQ(a.freeRangeCount(), 1u);
}

}  // namespace
}  // namespace caustics::rhi::vulkan
