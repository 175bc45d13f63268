// The sphere TLAS capacity policy (caustics/sphere_capacity.h): W x H without an earlier count, else the
// earlier count with 1.25 x headroom rounded up to an eighth of a power of two, within
// [kMinSphereCapacity, W x H]; 0 after a frame without spheres. The allocation the capacity is clamped
// to: a sixteenth of the pixels (at least 131,072, at most W x H), grown to what a frame asked for.
#include <gtest/gtest.h>

#include "caustics/sphere_capacity.h"

namespace caustics {
namespace {

constexpr uint32_t kPixels = 1920 * 1080;

TEST(SphereCapacity, WithoutAnEarlierCountEveryPixelHasASlot) {
    EXPECT_EQ(sphereTlasCapacity(std::nullopt, kPixels), kPixels);
}

TEST(SphereCapacity, EarlierCountGetsHeadroomRoundedUpToABucket) {
    // 100,000 x 1.25 = 125,000; buckets of 2^17 / 8 = 16,384: 131,072.
    EXPECT_EQ(sphereTlasCapacity(100000u, kPixels), 131072u);
    for (uint32_t count : {1000u, 4321u, 65536u, 200000u, 1000000u}) {
        const uint32_t c = sphereTlasCapacity(count, kPixels);
        EXPECT_GE(double(c), 1.25 * count) << count;
        EXPECT_LE(double(c), 1.45 * count) << count;
    }
}

TEST(SphereCapacity, SmallChangesOfTheCountKeepTheCapacity) {
    EXPECT_EQ(sphereTlasCapacity(100000u, kPixels), sphereTlasCapacity(103000u, kPixels));
}

TEST(SphereCapacity, ClampedToTheSmallestCapacityAndToEveryPixel) {
    EXPECT_EQ(sphereTlasCapacity(1u, kPixels), kMinSphereCapacity);
    EXPECT_EQ(sphereTlasCapacity(3u, kPixels), kMinSphereCapacity);
    EXPECT_EQ(sphereTlasCapacity(kPixels, kPixels), kPixels);
    EXPECT_EQ(sphereTlasCapacity(30u, 16u), 16u);
}

// A frame without spheres: the next frame of the slot builds and gathers nothing.
TEST(SphereCapacity, NoEarlierSphereMeansNoBuild) {
    EXPECT_EQ(sphereTlasCapacity(0u, kPixels), 0u);
}

TEST(SphereAllocation, FirstAllocationIsASixteenthOfThePixelsWithAFloor) {
    EXPECT_EQ(initialSphereAllocation(kPixels), kMinSphereAllocation);   // 129,600 at 1080p, under the floor
    EXPECT_EQ(initialSphereAllocation(3840u * 2160u), 3840u * 2160u / 16);
    EXPECT_EQ(initialSphereAllocation(640u * 480u), kMinSphereAllocation);
    EXPECT_EQ(initialSphereAllocation(320u * 240u), 320u * 240u) << "small images keep a slot per pixel";
}

TEST(SphereAllocation, GrowsToTheCapacityAFrameAskedForNeverShrinks) {
    const uint32_t first = initialSphereAllocation(kPixels);
    EXPECT_EQ(grownSphereAllocation(first, 0u, kPixels), first);
    const uint32_t wanted = sphereTlasCapacity(400000u, kPixels);
    EXPECT_EQ(grownSphereAllocation(first, wanted, kPixels), wanted);
    EXPECT_EQ(grownSphereAllocation(wanted, 1000u, kPixels), wanted) << "never shrinks";
    EXPECT_EQ(grownSphereAllocation(first, 2 * kPixels, kPixels), kPixels) << "at most W x H";
    // A smaller view sharing it keeps the larger allocation.
    EXPECT_EQ(grownSphereAllocation(wanted, 0u, 64u * 48u), wanted);
}

}  // namespace
}  // namespace caustics
