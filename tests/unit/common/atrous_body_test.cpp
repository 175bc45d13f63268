// The caustic filter's a-trous body (passes/caustic_filter/shaders/atrous.h) compiled as C++: the
// region a group loads into shared memory, and the spreading weight (docs/caustics.md "Filter", "Cost").
#include <gtest/gtest.h>

#include <cmath>

#include "caustic_filter/shaders/atrous.h"

namespace caustics::shader {
namespace {

// Up to kAtrousSharedMaxStep every tap of every pixel of a tile lies in the tile's region (the shared
// arrays hold it) and in one of the 3x3 tiles around it (the slot-map entries the group loads); the
// largest region fits the arrays. Larger steps fetch each tap instead.
TEST(AtrousBody, EveryTapOfATileLiesInItsRegionUpToTheSharedStep) {
    EXPECT_EQ(atrousRegionSide(kAtrousSharedMaxStep), kAtrousMaxRegionSide);
    EXPECT_TRUE(atrousUsesRegion(kAtrousSharedMaxStep));
    EXPECT_FALSE(atrousUsesRegion(2 * kAtrousSharedMaxStep));
    const int2 tile(5, 3);
    for (int s = 1; s <= kAtrousSharedMaxStep; s *= 2) {
        const int2 origin = tile * kFilterTileSize - int2(atrousApron(s));
        const int side = atrousRegionSide(s);
        for (int j = 0; j < kFilterTileSize; ++j)
            for (int i = 0; i < kFilterTileSize; ++i)
                for (int dy = -2; dy <= 2; ++dy)
                    for (int dx = -2; dx <= 2; ++dx) {
                        const int2 q = tile * kFilterTileSize + int2(i, j) + int2(dx, dy) * s;
                        const int2 at = q - origin;
                        ASSERT_TRUE(at.x >= 0 && at.y >= 0 && at.x < side && at.y < side) << "step " << s;
                        const int n = atrousNeighbourTileIndex(q / kFilterTileSize, tile);
                        ASSERT_TRUE(n >= 0 && n < 9) << "step " << s;
                    }
    }
    // The 3x3 indices are distinct and row-major.
    EXPECT_EQ(atrousNeighbourTileIndex(tile + int2(-1, -1), tile), 0);
    EXPECT_EQ(atrousNeighbourTileIndex(tile, tile), 4);
    EXPECT_EQ(atrousNeighbourTileIndex(tile + int2(1, 1), tile), 8);
}

// The weights: the B3 kernel's 25 taps sum to 1; on a plane (depth along the gradient), equal normals
// and equal luminance every weight is the kernel tap; a luminance difference of 3 deviations of the
// difference keeps exp(-4.5) of it, a normal 10 degrees off cos(10 deg)^128 (0.14).
TEST(AtrousBody, SpreadWeightIsTheKernelOnAPlaneAndStopsAtEdges) {
    float sum = 0.0f;
    const float2 grad(0.01f, -0.02f);
    const float3 n(0.0f, 0.0f, 1.0f);
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            const int2 offset = int2(dx, dy) * 2;
            const float zp = 5.0f + glm::dot(grad, float2(offset));
            const float w = atrousSpreadWeight(offset, 2, 5.0f, zp, grad, n, n, 1.0f, 1.0f, 0.1f, 0.1f, 1.0f);
            // zp's float rounding (half an ulp at 5, 2.4e-7) over the depth term's scale (>= 0.02): <= 1.2e-5.
            const float tap = atrousKernelTap(std::abs(dx)) * atrousKernelTap(std::abs(dy));
            EXPECT_NEAR(w, tap, 2e-5f * tap);
            sum += w;
        }
    EXPECT_NEAR(sum, 1.0f, 2e-5f);
    const float centre = atrousKernelTap(0) * atrousKernelTap(0);
    // Var_q + Var_p = 0.02, sigma 1: a difference of 3 sqrt(0.02) is 3 deviations.
    const float lum = atrousSpreadWeight(int2(0), 1, 5.0f, 5.0f, grad, n, n, 1.0f, 1.0f + 3.0f * std::sqrt(0.02f), 0.01f,
                                         0.01f, 1.0f);
    EXPECT_NEAR(lum / centre, std::exp(-4.5f), 1e-5f);
    const float c10 = std::cos(glm::radians(10.0f));
    const float3 tilted(std::sin(glm::radians(10.0f)), 0.0f, c10);
    EXPECT_NEAR(atrousSpreadWeight(int2(0), 1, 5.0f, 5.0f, grad, n, tilted, 1.0f, 1.0f, 0.01f, 0.01f, 1.0f) / centre,
                std::pow(c10, 128.0f), 1e-5f);
}

}  // namespace
}  // namespace caustics::shader
