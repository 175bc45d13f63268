// The sphere TLAS capacity policy (caustics/sphere_capacity.h): W x H without an earlier count, else the
// earlier count with 1.25 x headroom rounded up to an eighth of a power of two, within
// [kMinSphereCapacity, W x H]; 0 after a frame without spheres.
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

}  // namespace
}  // namespace caustics
