// Fractional rays per texel (paper section 4 measures 0.25 .. 25): sample s of a texel is emitted
// with probability clamp(r - s, 0, 1), so the launched count is binomial around r x (emitting texels).
#include <gtest/gtest.h>

#include <cmath>

#include "caustic_harness.h"
#include "caustic_test_scene.h"
#include "gpu_test.h"

namespace caustics::test {
namespace {

class CausticEmission : public GpuTest {
protected:
    uint32_t raysFor(float raysPerTexel) {
        CausticsSettings s = smallSettings();
        s.raysPerTexel = raysPerTexel;
        s.secondType = false;
        auto run = runCaustics(*device, smallGlassSphereScene(), obliqueCamera(), 32, 32, s);
        EXPECT_TRUE(run) << run.message();
        return run ? run.value().raysOfLight(0) : 0u;
    }
};

TEST_F(CausticEmission, FractionalRaysPerTexelEmitTheExpectedFractionWithinFourSigma) {
    const double texels = raysFor(1.0f);   // every emitting texel launches exactly one ray at r = 1
    ASSERT_GT(texels, 500.0);
    for (float r : {0.25f, 0.5f, 2.5f}) {
        const double fraction = r - std::floor(r);
        // Binomial(texels, fraction) on top of floor(r) x texels: 4 standard deviations (two-sided
        // false-failure probability 6e-5 per value).
        const double sigma = std::sqrt(texels * fraction * (1.0 - fraction));
        const double got = raysFor(r);
        EXPECT_NEAR(got, r * texels, 4.0 * sigma + 1.0) << "raysPerTexel " << r;
    }
}

TEST_F(CausticEmission, WholeRaysPerTexelEmitExactlyThatManyRaysPerTexel) {
    const uint32_t texels = raysFor(1.0f);
    EXPECT_EQ(raysFor(3.0f), 3u * texels);
}

}  // namespace
}  // namespace caustics::test
