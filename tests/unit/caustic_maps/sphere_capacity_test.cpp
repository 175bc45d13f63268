// The sphere TLAS capacity policy (caustics/sphere_capacity.h): the slot limit (kMaxSpheresPerPixel x W x
// H, the lobe branches) without an earlier count, else the earlier count with 1.25 x headroom rounded up
// to an eighth of a power of two, within [kMinSphereCapacity, slot limit]; 0 after a frame without
// spheres. The allocation the capacity is clamped to: the specular surfaces' coverage (at least
// kMinSphereAllocation, at most the slot limit), grown to what a frame asked for.
#include <gtest/gtest.h>

#include "caustics/sphere_capacity.h"

namespace caustics {
namespace {

constexpr uint32_t kPixels = 1920 * 1080;

TEST(SphereCapacity, WithoutAnEarlierCountEveryPixelHasASlot) {
    EXPECT_EQ(sphereTlasCapacity(std::nullopt, kPixels), kPixels);
}

// Each specular pixel's launch may append its most probable path's sphere and one lobe branch's.
TEST(SphereCapacity, TheSlotLimitHoldsEveryBranchOfEveryPixel) {
    EXPECT_EQ(sphereSlotLimit(kPixels), kMaxSpheresPerPixel * kPixels);
    EXPECT_EQ(kMaxSpheresPerPixel, 2u);
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

// The first allocation follows the specular surfaces in view (their bounding spheres' coverage, bucketed
// like a capacity), not the image size.
TEST(SphereAllocation, FirstAllocationFollowsTheSpecularSurfacesInView) {
    const uint32_t uhd = 3840u * 2160u;
    EXPECT_EQ(initialSphereAllocation(kPixels, 0.0), kMinSphereAllocation) << "nothing specular in view: the floor";
    EXPECT_EQ(initialSphereAllocation(uhd, 0.0), kMinSphereAllocation) << "whatever the image size";
    EXPECT_GE(initialSphereAllocation(kPixels, 1.0), kPixels) << "specular everywhere: a slot per pixel";
    EXPECT_LE(initialSphereAllocation(kPixels, 1.0), uint32_t(1.02 * kPixels)) << "bucketed, not the slot limit";
    // 1 % of a 4K image: 82,944 slots, rounded up to the bucket (2^14 past 2^16): 98,304.
    EXPECT_EQ(initialSphereAllocation(uhd, 0.01), 98304u);
    EXPECT_GE(initialSphereAllocation(uhd, 0.01), uint32_t(kSpecularCoverageMargin * 0.01 * uhd));
    EXPECT_EQ(initialSphereAllocation(128u * 128u, 0.0), 2u * 128u * 128u) << "128x128 test images get two slots per pixel";
    EXPECT_EQ(initialSphereAllocation(64u * 64u, 0.5), sphereSlotLimit(64u * 64u)) << "at most the slot limit";
}

TEST(SphereAllocation, GrowsToTheCapacityAFrameAskedForNeverShrinks) {
    const uint32_t first = initialSphereAllocation(kPixels, 0.01);
    EXPECT_EQ(grownSphereAllocation(first, 0u, first, kPixels), first);
    const uint32_t wanted = sphereTlasCapacity(400000u, kPixels);
    EXPECT_EQ(grownSphereAllocation(first, wanted, first, kPixels), wanted);
    EXPECT_EQ(grownSphereAllocation(wanted, 1000u, first, kPixels), wanted) << "never shrinks";
    EXPECT_EQ(grownSphereAllocation(first, 2 * kPixels, first, kPixels), kPixels) << "at most the slot limit";
    // More specular surfaces come into view: the allocation grows to their estimate at once.
    const uint32_t more = initialSphereAllocation(kPixels, 0.2);
    EXPECT_EQ(grownSphereAllocation(first, 0u, more, kPixels), more);
    // A smaller view sharing it keeps the larger allocation.
    EXPECT_EQ(grownSphereAllocation(wanted, 0u, kMinSphereAllocation, 64u * 48u), wanted);
}

}  // namespace
}  // namespace caustics
