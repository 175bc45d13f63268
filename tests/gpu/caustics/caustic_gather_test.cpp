// Second-type gather (paper 3.3) against a CPU brute force over the same stored hits and gather disks,
// and the bounded hit buffer's overflow accounting.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/packing.hpp>

#include "caustic_harness.h"
#include "common/gather_disk.h"
#include "caustic_test_scene.h"
#include "common/bsdf.h"
#include "gpu_test.h"

namespace caustics::test {
namespace {

// flux x f_r of a stored hit towards wo, from the hit's fields (shaders/common/caustic_hit.h; the
// directions decoded from their octahedral words as the gather decodes them).
glm::vec3 reflectedFlux(const CausticHit& h, const glm::vec3& wo) {
    glm::vec2 mr = glm::unpackUnorm2x16(h.metallicRoughness);
    auto brdf = shader::makeBrdfMaterial(h.baseColor, mr.x, mr.y, h.transmission, h.dielectricF0);
    return h.flux * shader::evalGltfBrdf(brdf, causticHitNormal(h), causticHitIncoming(h), wo);
}

class CausticGather : public GpuTest {};

TEST_F(CausticGather, SecondTypeEqualsCpuBruteForceGatherOnTheSameHitsAndSpheres) {
    scene::Scene scene = smallGlassSphereScene();
    auto run = runCaustics(*device, scene, obliqueCamera(), 96, 96, smallSettings());
    ASSERT_TRUE(run) << run.message();
    const CausticRun& r = run.value();
    ASSERT_GT(r.hits.size(), 100u);
    ASSERT_EQ(r.spheres.size(), size_t(r.stats[kStatSpheres]));
    ASSERT_EQ(r.stats[kStatSpheresDropped], 0u);
    ASSERT_GT(r.stats[kStatSpheres], 50u) << "too few pixels see the plane through the glass";
    std::vector<glm::dvec3> expected(size_t(96 * 96), glm::dvec3(0.0));
    uint64_t pairs = 0;
    for (const CausticSphere& s : r.spheres) {
        if (s.radius <= 0.0f) continue;
        for (const CausticHit& h : r.hits) {
            // The disk test sphere.rint evaluates (common/gather_disk.h); points within 1e-6 of the
            // boundary could round either way, and are rare enough (measure zero) not to matter here.
            if (!shader::insideGatherDisk(h.position, s.centre, s.normal, s.radius)) continue;
            if (h.objectId != s.objectId || glm::dot(causticHitNormal(h), s.normal) <= 0.0f) continue;
            expected[s.pixel] += glm::dvec3(reflectedFlux(h, s.outgoing) * s.transmittance) / (3.14159265358979 * s.radius * s.radius);
            ++pairs;
        }
    }
    EXPECT_EQ(uint64_t(r.stats[kStatGatherHits]), pairs);
    ASSERT_GT(pairs, 0u) << "the test would not exercise the gather";
    double maxValue = 0.0;
    for (const auto& e : expected) maxValue = std::max(maxValue, std::max(e.x, std::max(e.y, e.z)));
    uint32_t wrong = 0;
    for (size_t i = 0; i < expected.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            // Float atomics add in an arbitrary order: allow 1e-4 relative plus 1e-6 of the image max.
            double got = r.secondType[i][c], want = expected[i][c];
            if (std::abs(got - want) > 1e-4 * std::abs(want) + 1e-6 * maxValue && ++wrong <= 5)
                ADD_FAILURE() << "pixel " << i << " channel " << c << ": GPU " << got << ", CPU " << want;
        }
    }
    EXPECT_EQ(wrong, 0u);
}

TEST_F(CausticGather, HitBufferOverflowIsCountedAndReportedNotACrash) {
    scene::Scene scene = smallGlassSphereScene();
    CausticsSettings s = smallSettings();
    s.maxStoredHits = 32;
    auto run = runCaustics(*device, scene, obliqueCamera(), 64, 64, s);
    ASSERT_TRUE(run) << run.message();
    const CausticRun& r = run.value();
    const uint32_t attempts = r.stats[kStatStoredHitAttempts];
    EXPECT_GT(attempts, 32u * 10u) << "the scene must produce far more hits than the buffer holds";
    ASSERT_EQ(r.hits.size(), 32u);
    for (const CausticHit& h : r.hits) {
        EXPECT_NE(h.objectId, 0u);
        EXPECT_TRUE(std::isfinite(h.flux.x) && h.flux.x >= 0.0f);
        EXPECT_NEAR(glm::length(causticHitIncoming(h)), 1.0f, 1e-4f);
    }
    for (const glm::vec3& v : r.secondType) ASSERT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
}

}  // namespace
}  // namespace caustics::test
