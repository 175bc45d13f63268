// The filter's half-precision pool (docs/caustics.md "Filter", "Memory"): the history and the temporal
// result are stored as radiance x pre-exposure in RGBA16F. With a still camera and temporal accumulation
// only, frame 2's output is half((h0 + frame 1) / 2) in every tile that frame 0's photons reached (those
// keep a history), h0 = half(frame 0); the rest is 32-bit. So its error against the 32-bit mean of the two
// unfiltered frames is at most half an ulp per rounding (2^-11 relative), at any pre-exposure that keeps the
// values inside half's range: the bound is the format's, not a measured noise. The one measured term is the
// still camera's reprojection, a float rounding off the texel centre (kLeak, below).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "caustic_harness.h"
#include "caustic_test_scene.h"
#include "gpu_test.h"
#include "caustics/scene/builtin_scenes.h"

namespace caustics::test {
namespace {

constexpr uint32_t kSize = 96;
// Bilinear weight a still camera's reprojection can give a neighbouring history texel (world position
// from depth and back, in float): measured up to 3.3e-5 on this view (2026-12-01); the bound allows 1e-3.
constexpr double kLeak = 1e-3;

CausticsSettings temporalOnly(float exposure) {
    CausticsSettings s;
    s.mapResolution = 96;
    s.raysPerTexel = 1.0f;
    s.secondType = false;
    s.maxStoredHits = 1u << 10;
    s.filter = true;
    s.atrousIterations = 0;
    s.exposure = exposure;
    return s;
}

std::vector<glm::vec3> unfiltered(const CausticRun& r) {
    std::vector<glm::vec3> out(r.firstType.size());
    for (size_t i = 0; i < out.size(); ++i) out[i] = r.firstType[i] + r.secondType[i];
    return out;
}

class CausticFilterPrecision : public GpuTest {};

// Exposures 1/64, 1 and 64: the ball's brightest pixel (~30 in radiance units) times 64 stays below
// half's 65504, its dimmest lit pixels (~0.05) divided by 64 above half's smallest normal 6.1e-5.
TEST_F(CausticFilterPrecision, HalfPrecisionHistoryIsWithinHalfAnUlpPerStoreOfTheMean) {
    for (float exposure : {1.0f / 64.0f, 1.0f, 64.0f}) {
        const CausticsSettings s = temporalOnly(exposure);
        auto first = runCaustics(*device, filterBallScene(), towardsTheFilterBallSpot(), kSize, kSize, s, 1);
        auto second = runCaustics(*device, filterBallScene(), towardsTheFilterBallSpot(), kSize, kSize, s, 2);
        ASSERT_TRUE(first) << first.message();
        ASSERT_TRUE(second) << second.message();
        const std::vector<glm::vec3> f0 = unfiltered(first.value()), f1 = unfiltered(second.value());
        const std::vector<glm::vec3>& out = second.value().radiance;
        double signedError = 0.0, worst = 0.0, worstLeak = 0.0, sumError = 0.0, sum = 0.0, brightest = 0.0;
        size_t lit = 0;
        std::vector<bool> kept(size_t(kSize / 8) * (kSize / 8), false);   // tiles frame 0's photons reached
        auto tileOf = [](size_t i) { return (i / kSize / 8) * (kSize / 8) + (i % kSize) / 8; };
        for (size_t i = 0; i < out.size(); ++i)
            if (f0[i] != glm::vec3(0.0f)) kept[tileOf(i)] = true;
        for (size_t i = 0; i < out.size(); ++i)
            for (int c = 0; c < 3; ++c) {
                if (!kept[tileOf(i)]) continue;
                const double mean = 0.5 * (double(f0[i][c]) + double(f1[i][c]));
                const double error = std::abs(double(out[i][c]) - mean);
                sumError += error;
                signedError += double(out[i][c]) - mean;
                sum += mean;
                brightest = std::max(brightest, double(f0[i][c]));
                // The still camera's reprojection lands a float rounding off the texel centre: the bilinear
                // taps mix in up to kLeak of a neighbour's history, so the largest difference to a neighbour
                // in frame 0 counts too (halved by the mean).
                double contrast = 0.0;
                const int x = int(i % kSize), y = int(i / kSize);
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int qx = x + dx, qy = y + dy;
                        if (qx < 0 || qy < 0 || qx >= int(kSize) || qy >= int(kSize)) continue;
                        contrast = std::max(contrast, std::abs(double(f0[size_t(qy) * kSize + qx][c]) - double(f0[i][c])));
                    }
                // Two roundings to half: frame 0's history (halved by the mean) and the temporal result
                // the output pass reads, each within half an ulp (the shaders round to nearest themselves,
                // filterNearestHalf; lavapipe's own conversion truncates, which measured 1.8 of this bound):
                // 2^-11 relative, 2^-25 absolute below half's smallest normal (in radiance units:
                // / exposure); plus 32-bit rounding (the photon sums' atomic order differs between the
                // runs: a few 1e-7 relative).
                auto halfUlpOf = [&](double v) { return std::ldexp(v, -11) + std::ldexp(1.0, -25) / exposure; };
                const double bound = 0.5 * halfUlpOf(f0[i][c]) + halfUlpOf(mean);
                const double rest = error - 4e-6 * mean - bound;
                if (rest > 0.0) worstLeak = std::max(worstLeak, contrast > 0.0 ? rest / (0.5 * contrast) : 1.0);
                if (f0[i][c] > 0.0f) ++lit;
                const double ratio = (error - 4e-6 * mean - kLeak * 0.5 * contrast) / bound;
                worst = std::max(worst, ratio);
            }
        std::printf("[ measured ] exposure %-8g lit channels %zu  brightest %.3g  worst error %.3f of the bound, "
                    "leak %.2g, L1 %.3g, signed %.2g\n", exposure, lit, brightest, worst, worstLeak, sumError / sum, signedError / sum);
        ASSERT_GT(lit, 100u);
        EXPECT_LE(worst, 1.0);
    }
}

}  // namespace
}  // namespace caustics::test
