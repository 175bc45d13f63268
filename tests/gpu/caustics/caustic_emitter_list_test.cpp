// caustics.emitters compacts the emitting map texels so that caustics.forward launches where photons
// leave (docs/caustics.md, "Cost"), with the flux estimator unchanged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "caustic_harness.h"
#include "caustic_test_scene.h"
#include "caustics/scene/builtin_scenes.h"
#include "gpu_test.h"

namespace caustics::test {
namespace {

uint64_t photons(const CausticRun& run) {
    uint64_t sum = 0;
    for (uint32_t l = 0; l < kMaxCausticLights; ++l) sum += run.raysOfLight(l);
    return sum;
}

double firstTypeEnergy(const CausticRun& run) {
    double sum = 0.0;
    for (const glm::vec3& c : run.firstType) sum += double(c.r) + c.g + c.b;
    return sum;
}

class CausticEmitterList : public GpuTest {
protected:
    Result<CausticRun> run(const scene::Scene& sc, const scene::Camera& camera, CausticsSettings s) {
        s.secondType = false;
        return runCaustics(*device, sc, camera, 64, 48, s);
    }
};

// Before the emitter list the forward grid covered every map texel: 8.7 % of them emitted on the
// atrium stand-in (issue 11); the target is >= 50 %.
TEST_F(CausticEmitterList, AtLeastHalfOfTheDispatchedTexelsEmitOnTheBuiltInScene) {
    auto sc = scene::makeBuiltin("builtin");
    ASSERT_TRUE(sc) << sc.message();
    CausticsSettings s = smallSettings();
    s.mapResolution = 128;
    auto r = run(sc.value(), sc->cameras.empty() ? obliqueCamera() : sc->cameras.front(), s);
    ASSERT_TRUE(r) << r.message();
    const uint64_t dispatched = r->stats[kStatDispatchedTexels];
    const uint64_t launched = photons(r.value());
    ASSERT_GT(r->plan.maps.size(), 0u);
    ASSERT_GT(dispatched, 0u);
    EXPECT_LE(dispatched, uint64_t(s.mapResolution) * s.mapResolution * r->plan.maps.size());
    EXPECT_GE(double(launched), 0.5 * double(dispatched))
        << launched << " photons from " << dispatched << " dispatched texels (" << r->stats[kStatEmitterTexels]
        << " listed)";
    // Segments: every photon traces at least its first segment, at most depth + 2.
    EXPECT_GE(r->stats[kStatForwardSegments], launched);
    EXPECT_LE(r->stats[kStatForwardSegments], launched * (s.maxSpecularDepth + 2));
}

// The forward grid is (listed texel, sample): at 2 rays per texel every listed texel launches sample 0
// (the same photon as at 1 ray per texel, same random stream) and sample 1, each with half the flux.
// The total first-type energy of the glass-sphere scene must be the same at 1 and 2 rays per texel
// (each the mean of kSeeds frames of different seeds). Threshold: 4 standard errors of the ratio from
// the per-seed spread measured in the same run, and the spread itself is bounded so that a noisy
// estimator cannot pass. Printed numbers are in the test log (docs/caustics.md, "Cost that follows
// the caustic work", has a measured run).
TEST_F(CausticEmitterList, FirstTypeEnergyIsTheSameAtTwoRaysPerTexel) {
    constexpr uint32_t kSeeds = 4;
    auto meanEnergy = [&](float raysPerTexel, double& relStd) {
        double sum = 0.0, sumSq = 0.0;
        for (uint32_t seed = 1; seed <= kSeeds; ++seed) {
            CausticsSettings s = smallSettings();
            s.mapResolution = 96;
            s.raysPerTexel = raysPerTexel;
            s.seed = seed;
            auto r = run(smallGlassSphereScene(), obliqueCamera(), s);
            EXPECT_TRUE(r) << r.message();
            const double e = r ? firstTypeEnergy(r.value()) : 0.0;
            sum += e;
            sumSq += e * e;
        }
        const double mean = sum / kSeeds;
        relStd = mean > 0.0 ? std::sqrt(std::max(0.0, sumSq / kSeeds - mean * mean) * kSeeds / (kSeeds - 1)) / mean : 0.0;
        return mean;
    };
    double stdOne = 0.0, stdTwo = 0.0;
    const double one = meanEnergy(1.0f, stdOne);
    const double two = meanEnergy(2.0f, stdTwo);
    ASSERT_GT(one, 0.0);
    const double sigmaRatio = std::sqrt((stdOne * stdOne + stdTwo * stdTwo) / kSeeds);
    std::printf("first-type energy: r=1 %.6g (rel std %.4f), r=2 %.6g (rel std %.4f), ratio %.4f, sigma %.4f\n",
                one, stdOne, two, stdTwo, two / one, sigmaRatio);
    EXPECT_LT(stdOne, 0.05);
    EXPECT_NEAR(two / one, 1.0, 4.0 * sigmaRatio);
}

// caustics.gather is dispatched from the stored-hit count (caustics.gatherGrid), not for
// CausticsSettings::maxStoredHits: one launch per stored hit, and at most the buffer's capacity when
// it overflows.
TEST_F(CausticEmitterList, GatherLaunchesOncePerStoredHit) {
    if (!device->capabilities().rayTracingIndirect) GTEST_SKIP() << "no indirect ray dispatch";
    for (uint32_t maxStoredHits : {1u << 16, 64u}) {
        CausticsSettings s = smallSettings();
        s.maxStoredHits = maxStoredHits;
        auto r = runCaustics(*device, smallGlassSphereScene(), obliqueCamera(), 64, 48, s);
        ASSERT_TRUE(r) << r.message();
        const uint32_t offered = r->stats[kStatStoredHitAttempts];
        ASSERT_GT(offered, 64u);
        EXPECT_EQ(r->stats[kStatGatherLaunches], std::min(offered, maxStoredHits)) << "maxStoredHits " << maxStoredHits;
    }
}

}  // namespace
}  // namespace caustics::test
