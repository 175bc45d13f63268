#include <gtest/gtest.h>

#include "common/rng.h"

namespace sh = caustics::shader;

// Pearson chi-square over 100 equal bins with 1e6 draws: 99 degrees of freedom, critical value
// 148.2 at p = 0.001. The seeds are fixed, so the test is deterministic; a generator with a bias of
// 1% in one bin would score > 200.
TEST(Rng, UniformFloatsPassChiSquareAtOneInAThousand) {
    constexpr int kBins = 100;
    constexpr int kDraws = 1000000;
    for (uint32_t pixel : {0u, 12345u}) {
        sh::Rng rng = sh::rngCreate(pixel, 3u, 0u, 42u);
        std::vector<int> counts(kBins, 0);
        for (int i = 0; i < kDraws; ++i) {
            float u = sh::rngNextFloat(rng);
            ASSERT_GE(u, 0.0f);
            ASSERT_LT(u, 1.0f);
            ++counts[int(u * kBins)];
        }
        double expected = double(kDraws) / kBins, chi2 = 0;
        for (int c : counts) chi2 += (c - expected) * (c - expected) / expected;
        EXPECT_LT(chi2, 148.2) << "pixel " << pixel;
    }
}

// Across streams: the first draw of 1e5 neighbouring pixels must be uniform too (per-pixel seeding
// is what the GPU passes rely on). Same 148.2 threshold.
TEST(Rng, FirstDrawsOfNeighbouringPixelsAreUniform) {
    constexpr int kBins = 100;
    std::vector<int> counts(kBins, 0);
    constexpr int kPixels = 100000;
    for (uint32_t p = 0; p < kPixels; ++p) {
        sh::Rng rng = sh::rngCreate(p, 0u, 0u, 0u);
        ++counts[int(sh::rngNextFloat(rng) * kBins)];
    }
    double expected = double(kPixels) / kBins, chi2 = 0;
    for (int c : counts) chi2 += (c - expected) * (c - expected) / expected;
    EXPECT_LT(chi2, 148.2);
}

TEST(Rng, SameKeysGiveSameStreamAndAnyKeyChangesIt) {
    sh::Rng a = sh::rngCreate(5, 6, 7, 8), b = sh::rngCreate(5, 6, 7, 8);
    for (int i = 0; i < 10; ++i) EXPECT_EQ(sh::rngNextUint(a), sh::rngNextUint(b));
    uint32_t base = sh::rngCreate(5, 6, 7, 8).state;
    EXPECT_NE(sh::rngCreate(6, 6, 7, 8).state, base);
    EXPECT_NE(sh::rngCreate(5, 7, 7, 8).state, base);
    EXPECT_NE(sh::rngCreate(5, 6, 8, 8).state, base);
    EXPECT_NE(sh::rngCreate(5, 6, 7, 9).state, base);
}
