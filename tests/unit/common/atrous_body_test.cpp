// The caustic filter's a-trous body (passes/caustic_filter/shaders/atrous.h) compiled as C++: the pair
// weight, its symmetry, the 12 pairs a pixel holds and their 10-bit packing (docs/caustics.md "Filter",
// "Cost").
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>

#include "caustic_filter/shaders/atrous.h"

namespace caustics::shader {
namespace {

// The weights: the B3 kernel's 25 taps sum to 1; on a plane (depth along the gradient), equal normals
// and equal luminance every weight is the kernel tap; a luminance difference of 3 deviations of the
// difference keeps exp(-4.5) of it, a normal 10 degrees off cos(10 deg)^128 (0.14).
TEST(AtrousBody, PairWeightIsTheKernelOnAPlaneAndStopsAtEdges) {
    float sum = 0.0f;
    const float2 grad(0.01f, -0.02f);
    const float3 n(0.0f, 0.0f, 1.0f);
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            const int2 offset = int2(dx, dy) * 2;
            const float zq = 5.0f + glm::dot(grad, float2(offset));
            const float w = atrousPairWeight(int2(dx, dy), 2, 5.0f, zq, grad, grad, n, n, 1.0f, 1.0f, 0.1f, 0.1f, 1.0f, 0.0f);
            // zq's float rounding (half an ulp at 5, 2.4e-7) over the depth term's scale (>= 0.02): <= 1.2e-5.
            const float tap = atrousKernelTap(std::abs(dx)) * atrousKernelTap(std::abs(dy));
            EXPECT_NEAR(w, tap, 2e-5f * tap);
            sum += w;
        }
    EXPECT_NEAR(sum, 1.0f, 2e-5f);
    const float centre = atrousKernelTap(0) * atrousKernelTap(0);
    EXPECT_EQ(centre, kAtrousSelfWeight);
    // Var_p + Var_q = 0.02, sigma 1: a difference of 3 sqrt(0.02) is 3 deviations.
    const float lum = atrousPairWeight(int2(0), 1, 5.0f, 5.0f, grad, grad, n, n, 1.0f, 1.0f + 3.0f * std::sqrt(0.02f), 0.01f,
                                       0.01f, 1.0f, 0.0f);
    EXPECT_NEAR(lum / centre, std::exp(-4.5f), 1e-5f);
    const float c10 = std::cos(glm::radians(10.0f));
    const float3 tilted(std::sin(glm::radians(10.0f)), 0.0f, c10);
    EXPECT_NEAR(atrousPairWeight(int2(0), 1, 5.0f, 5.0f, grad, grad, n, tilted, 1.0f, 1.0f, 0.01f, 0.01f, 1.0f, 0.0f) / centre,
                std::pow(c10, 128.0f), 1e-5f);
}

// w(p, q) = w(q, p) for pixels that differ in every guide (depth off the plane, slopes, normals,
// luminance, variance), with and without the jitter allowance: one evaluation serves both shares.
TEST(AtrousBody, PairWeightIsSymmetric) {
    const float3 np = glm::normalize(float3(0.1f, 0.05f, 1.0f)), nq = glm::normalize(float3(-0.05f, 0.1f, 1.0f));
    const float2 gp(0.01f, -0.02f), gq(0.03f, 0.005f);
    for (float jitter : {0.0f, 1.0f})
        for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx) {
                const int2 tap(dx, dy);
                const float zq = 5.0f + glm::dot(gp, float2(tap * 4)) + 0.01f * float(dx - dy);
                const float pq = atrousPairWeight(tap, 4, 5.0f, zq, gp, gq, np, nq, 1.0f, 1.3f, 0.05f, 0.02f, 1.0f, jitter);
                const float qp = atrousPairWeight(-tap, 4, zq, 5.0f, gq, gp, nq, np, 1.3f, 1.0f, 0.02f, 0.05f, 1.0f, jitter);
                EXPECT_NEAR(pq, qp, 1e-6f * std::max(pq, 1e-3f)) << dx << "," << dy << " jitter " << jitter;
                EXPECT_GT(pq, 0.0f);
            }
}

// The 12 taps a pixel holds and their negatives are the 24 non-centre taps of the 5x5 kernel, once each.
TEST(AtrousBody, PairTapsAndTheirNegativesCoverTheKernelOnce) {
    std::set<std::pair<int, int>> seen;
    for (int k = 0; k < kAtrousPairCount; ++k) {
        const int2 t = atrousPairTap(k);
        EXPECT_TRUE(t.y > 0 || (t.y == 0 && t.x > 0)) << "pair " << k << " is not after the pixel in scan order";
        EXPECT_LE(std::abs(t.x), 2);
        EXPECT_LE(t.y, 2);
        EXPECT_TRUE(seen.insert({t.x, t.y}).second);
        EXPECT_TRUE(seen.insert({-t.x, -t.y}).second);
    }
    EXPECT_EQ(seen.size(), 24u);
}

// The 10-bit weight: within 1/64 relative of the value from the kernel's largest off-centre tap down to
// 2^-25, 0 below, 0 for 0; each unpacked weight a whole number of 2^-30 fixed-point units (so W_q adds
// exactly); the code of 12 pairs packed into one texel reads back per index.
TEST(AtrousBody, PackedPairWeightsKeepOnePartIn64AndAddExactlyInFixedPoint) {
    EXPECT_EQ(atrousPackWeight(0.0f), 0u);
    EXPECT_EQ(atrousUnpackWeight(0u), 0.0f);
    EXPECT_EQ(atrousPackWeight(std::ldexp(1.0f, -26)), 0u);
    for (float w = 0.09375f; w >= std::ldexp(1.0f, -25); w *= 0.8731f) {
        const uint code = atrousPackWeight(w);
        ASSERT_LT(code, 1024u);
        const float unpacked = atrousUnpackWeight(code);
        EXPECT_NEAR(unpacked / w, 1.0f, 1.0f / 64.0f + 1e-6f) << w;
        EXPECT_EQ(double(atrousFixedWeight(unpacked)), double(unpacked) * 1073741824.0) << w;
    }
    EXPECT_EQ(double(atrousFixedWeight(kAtrousSelfWeight)), double(kAtrousSelfWeight) * 1073741824.0);
    // Values of the grid (5-bit mantissas) are kept exactly.
    for (float w : {0.0625f, 0.09375f, 0.140625f * 0.5f, std::ldexp(1.5f, -20)})
        EXPECT_EQ(atrousUnpackWeight(atrousPackWeight(w)), w);
    uint4 packed(0u);
    for (int k = 0; k < kAtrousPairCount; ++k) packed[k / 3] |= atrousPackWeight(0.01f * float(k + 1)) << (10 * (k % 3));
    for (int k = 0; k < kAtrousPairCount; ++k)
        EXPECT_EQ(atrousPairCode(packed, k), atrousPackWeight(0.01f * float(k + 1))) << "pair " << k;
}

}  // namespace
}  // namespace caustics::shader
