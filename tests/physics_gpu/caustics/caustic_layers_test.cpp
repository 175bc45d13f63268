// Caustics at game-level scale on the GPU (docs/caustics.md, "Layers per cluster", "Photon budget",
// "Light range"): a ball's caustic is as clean with glass 40 m away as alone, each layer gets the share
// of the photon budget its view coverage asks for while the energy stays unbiased, the level scene
// keeps within the budget and spends nothing out of view, and a point light's range ends its caustics.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numeric>

#include <glm/gtc/matrix_transform.hpp>

#include "caustic_harness.h"
#include "gpu_test.h"
#include "caustics/scene/builtin_scenes.h"

namespace caustics::test {
namespace {

constexpr uint32_t kSize = 128;

CausticsSettings layerSettings() {
    CausticsSettings s;
    s.mapResolution = 128;
    s.filter = false;
    s.secondType = false;
    s.maxStoredHits = 1u << 17;
    return s;
}

uint32_t firstSpecular(const scene::Scene& sc) {
    for (uint32_t i = 0; i < sc.instances.size(); ++i)
        if (sc.materials[sc.meshes[sc.instances[i].mesh].material].isSpecular()) return i;
    return 0;
}

// The scene: a glass ball (R 0.5 m, IOR 1.5, centre 1 m up) under a sun; `far` adds a second ball
// and a metal ring 40 m away.
scene::Scene ballScene(bool far) {
    scene::AnalyticSceneDesc d;
    d.planeHalfSize = 60.0f;
    d.tessellation = 64;
    scene::Scene sc = scene::makeGlassSphereScene(d);
    if (!far) return sc;
    scene::Instance ball = sc.instances[firstSpecular(sc)];
    ball.transform = glm::translate(glm::mat4(1.0f), {40.0f, 0.0f, 0.0f});
    sc.instances.push_back(ball);
    scene::Scene ring = scene::makeMetalRingScene();
    const uint32_t ringInstance = firstSpecular(ring);
    scene::Mesh mesh = ring.meshes[ring.instances[ringInstance].mesh];
    mesh.material = uint32_t(sc.materials.size());
    sc.materials.push_back(ring.materials[ring.meshes[ring.instances[ringInstance].mesh].material]);
    sc.meshes.push_back(mesh);
    sc.instances.push_back({uint32_t(sc.meshes.size() - 1), glm::translate(glm::mat4(1.0f), {41.5f, 0.0f, 1.0f}),
                            uint32_t(sc.instances.size() + 1)});
    return sc;
}

scene::Camera overTheCaustic() {
    scene::Camera cam;
    cam.eye = {0.0f, 2.6f, 1.6f};
    cam.target = {0.0f, 0.0f, 0.0f};
    cam.verticalFovRadians = glm::radians(35.0f);
    return cam;
}

double energy(const std::vector<glm::vec3>& img) {
    double e = 0.0;
    for (const glm::vec3& c : img) e += double(c.x + c.y + c.z);
    return e;
}

double relativeL1(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
    double diff = 0.0, sum = 0.0;
    for (size_t i = 0; i < a.size(); ++i) {
        diff += double(std::abs(a[i].x - b[i].x) + std::abs(a[i].y - b[i].y) + std::abs(a[i].z - b[i].z));
        sum += double(a[i].x + a[i].y + a[i].z + b[i].x + b[i].y + b[i].z) * 0.5;
    }
    return sum > 0.0 ? diff / sum : 0.0;
}

uint64_t emitted(const CausticRun& r) {
    uint64_t n = 0;
    for (const CausticLayerPlanGpu& p : r.layerPlans) n += p.emitted;
    return n;
}

class CausticLayersGpu : public GpuTest {};

// Before layers per cluster the far objects stretched the sun's one map over 41 m: seed-to-seed L1 of the
// ball's caustic went from 0.42 alone to 2.00 (issue 17). Now the ball's layer is fitted to it alone and
// the far cluster, out of view, gets no layer: the same photons, the same noise.
TEST_F(CausticLayersGpu, FarObjectsOutOfViewLeaveTheBallsCausticAsCleanAsAlone) {
    const scene::Camera cam = overTheCaustic();
    auto runSeed = [&](bool far, uint32_t seed) {
        CausticsSettings s = layerSettings();
        s.seed = seed;
        return runCaustics(*device, ballScene(far), cam, kSize, kSize, s);
    };
    auto alone1 = runSeed(false, 1), alone2 = runSeed(false, 2), far1 = runSeed(true, 1), far2 = runSeed(true, 2);
    for (auto* r : {&alone1, &alone2, &far1, &far2}) ASSERT_TRUE(*r) << r->message();
    ASSERT_EQ(far1->plan.maps.size(), 1u);
    EXPECT_EQ(far1->plan.hiddenClusters, 1u);
    const double noiseAlone = relativeL1(alone1->firstType, alone2->firstType);
    const double noiseFar = relativeL1(far1->firstType, far2->firstType);
    const double energyRatio = energy(far1->firstType) / energy(alone1->firstType);
    std::printf("[ measured ] seed-to-seed L1 alone %.4f, with far objects %.4f; energy ratio %.5f; photons %llu vs %llu\n",
                noiseAlone, noiseFar, energyRatio, (unsigned long long)emitted(alone1.value()),
                (unsigned long long)emitted(far1.value()));
    ASSERT_GT(energy(alone1->firstType), 0.0);
    EXPECT_LE(noiseFar, 1.25 * noiseAlone);
    EXPECT_NEAR(energyRatio, 1.0, 0.03);
    EXPECT_EQ(emitted(far1.value()), emitted(alone1.value())) << "the ball's layer emits the same photons";
}

// Two balls 6 m apart, both in view, under a 240k-photon budget: each layer emits its coverage share of
// the budget (fractional rounding: a few hundred photons), and each ball's caustic energy matches the
// paper's per-texel emission at 16 rays per texel within 3 %, whatever the split (measured 0.9993 and
// 1.0055; at a quarter of the photons 1.0019 and 0.9707: the bound is about 4 sd of this run's noise).
TEST_F(CausticLayersGpu, BudgetSharesFollowCoverageAndEnergyIsUnbiased) {
    scene::Scene sc = ballScene(false);
    scene::Instance second = sc.instances[firstSpecular(sc)];
    second.transform = glm::translate(glm::mat4(1.0f), {6.0f, 0.0f, 0.0f});
    sc.instances.push_back(second);
    scene::Camera cam;
    cam.eye = {-1.5f, 5.0f, 6.0f};
    cam.target = {3.0f, 0.0f, 0.0f};
    cam.verticalFovRadians = glm::radians(50.0f);
    CausticsSettings budget = layerSettings();
    budget.photonsPerFrame = 240000;
    CausticsSettings perTexel = layerSettings();
    perTexel.raysPerTexel = 16.0f;
    auto b = runCaustics(*device, sc, cam, kSize, kSize, budget);
    auto p = runCaustics(*device, sc, cam, kSize, kSize, perTexel);
    ASSERT_TRUE(b) << b.message();
    ASSERT_TRUE(p) << p.message();
    ASSERT_EQ(b->plan.maps.size(), 2u);
    ASSERT_EQ(b->layerPlans.size(), 2u);
    const double coverageSum = b->plan.coverage[0] + b->plan.coverage[1];
    for (size_t k = 0; k < 2; ++k) {
        const double expected = 240000.0 * b->plan.coverage[k] / coverageSum;
        std::printf("[ measured ] layer %zu: coverage %.4f, %u photons emitted, %.0f planned, %u emitting texels\n", k,
                    b->plan.coverage[k], b->layerPlans[k].emitted, expected, b->layerPlans[k].emitters);
        // Fractional emission: each texel's last photon is a Bernoulli draw, sd <= sqrt(texels) / 2.
        EXPECT_NEAR(double(b->layerPlans[k].emitted), expected, 3.0 * std::sqrt(double(b->layerPlans[k].emitters)) + 1.0);
    }
    // Energy per half of the image (ball 1's caustic left of the middle column, ball 2's right).
    auto half = [&](const std::vector<glm::vec3>& img, bool right) {
        double e = 0.0;
        for (uint32_t y = 0; y < kSize; ++y)
            for (uint32_t x = right ? kSize / 2 : 0; x < (right ? kSize : kSize / 2); ++x) {
                const glm::vec3 c = img[size_t(y) * kSize + x];
                e += double(c.x + c.y + c.z);
            }
        return e;
    };
    for (bool right : {false, true}) {
        const double ratio = half(b->firstType, right) / half(p->firstType, right);
        std::printf("[ measured ] %s ball: budget / per-texel caustic energy %.4f\n", right ? "right" : "left", ratio);
        EXPECT_NEAR(ratio, 1.0, 0.03);
    }
}

// The level scene: whatever the object count, the photons emitted are the budget (its fractional
// rounding aside), and lights whose every cluster is out of view emit nothing.
TEST_F(CausticLayersGpu, LevelSceneKeepsTheBudgetAndSpendsNothingOutOfView) {
    for (uint32_t objects : {12u, 48u}) {
        scene::LevelSceneDesc d;
        d.objects = objects;
        d.extent = 120.0f;
        scene::Scene level = scene::makeLevelScene(d);
        CausticsSettings s = layerSettings();
        s.mapResolution = 64;
        s.photonsPerFrame = 30000;
        auto r = runCaustics(*device, level, level.cameras.front(), 96, 54, s);
        ASSERT_TRUE(r) << r.message();
        uint64_t texels = 0;
        for (const CausticLayerPlanGpu& p : r->layerPlans) texels += p.emitters;
        const uint64_t photons = emitted(r.value());
        std::printf("[ measured ] level with %u objects: %zu layers, %u hidden clusters, %llu photons emitted of 30000\n",
                    objects, r->plan.maps.size(), r->plan.hiddenClusters, (unsigned long long)photons);
        EXPECT_GT(r->plan.hiddenClusters, 0u);
        // Spent whole too: a layer whose map lists no texel hands its share to the others.
        const double spread = 3.0 * std::sqrt(double(texels)) + double(r->plan.maps.size());
        EXPECT_LE(double(photons), 30000.0 + spread);
        EXPECT_GE(double(photons), 30000.0 - spread);
        std::vector<bool> lit(level.lights.size(), false);
        for (const CausticMapGpu& m : r->plan.maps) lit[m.light] = true;
        for (uint32_t l = 0; l < level.lights.size(); ++l)
            if (!lit[l]) {
                EXPECT_EQ(r->raysOfLight(l), 0u) << "light " << l << " has no layer in view";
            }
    }
}

// KHR_lights_punctual range: a point light 1.5 m over the ball (2.5 m over the floor) with a 2.7 m range. Every stored caustic
// hit (a deposit past the range carries no flux and is not stored) lies within the range; with an
// infinite range some lie beyond it (so the check can fail).
TEST_F(CausticLayersGpu, PointLightRangePutsNoCausticBeyondIt) {
    scene::Scene sc = ballScene(false);
    sc.lights.clear();
    scene::Light point;
    point.type = scene::LightType::Point;
    point.position = {0.3f, 2.5f, 0.0f};
    point.intensity = 20.0f;
    const float range = 2.7f;
    CausticsSettings s = layerSettings();
    s.secondType = true;   // the forward pass stores its diffuse hits only for the second type's gather
    auto beyond = [&](const CausticRun& r) {
        uint32_t n = 0, lit = 0;
        for (const CausticHit& h : r.hits) {
            ++lit;
            if (glm::length(h.position - point.position) > range) ++n;
        }
        return std::pair<uint32_t, uint32_t>{n, lit};
    };
    point.range = 0.0f;
    sc.lights = {point};
    auto infinite = runCaustics(*device, sc, overTheCaustic(), kSize, kSize, s);
    point.range = range;
    sc.lights = {point};
    auto ranged = runCaustics(*device, sc, overTheCaustic(), kSize, kSize, s);
    ASSERT_TRUE(infinite) << infinite.message();
    ASSERT_TRUE(ranged) << ranged.message();
    auto [farInfinite, litInfinite] = beyond(infinite.value());
    auto [farRanged, litRanged] = beyond(ranged.value());
    std::printf("[ measured ] hits beyond %.1f m: infinite range %u of %u, range %.1f m %u of %u\n", range, farInfinite,
                litInfinite, range, farRanged, litRanged);
    EXPECT_GT(farInfinite, 100u);
    EXPECT_LT(farInfinite, litInfinite) << "part of the caustic lies inside the range";
    EXPECT_GT(litRanged, 100u);
    EXPECT_EQ(farRanged, 0u);
}

}  // namespace
}  // namespace caustics::test
