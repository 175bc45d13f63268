// The GPU first-type caustics against the CPU reference light tracer (engine/reference, same
// estimator and emission maps), and the map planner's light skipping (paper 3.2, Figure 3).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "caustic_harness.h"
#include "gpu_test.h"
#include "image_analysis.h"
#include "caustics/reference/reference_tracer.h"
#include "caustics/scene/builtin_scenes.h"

namespace caustics::test {
namespace {

constexpr uint32_t kSize = 96;

class CausticReference : public GpuTest {};

scene::Scene sphereScene() {
    scene::AnalyticSceneDesc d;
    d.radius = 0.5f;
    d.height = 0.8f;
    d.tessellation = 48;
    d.lightDirection = glm::normalize(glm::vec3(0.3f, -1.0f, 0.0f));
    return scene::makeGlassSphereScene(d);
}

scene::Camera sphereCamera() {
    scene::Camera c;
    c.eye = {0.0f, 1.6f, 2.2f};
    c.target = {-0.1f, 0.2f, 0.0f};
    c.verticalFovRadians = glm::radians(50.0f);
    return c;
}

// Relative L1 error sum|gpu - ref| / sum(ref) over the caustic pixels (reference luminance above 2 %
// of its maximum).
double relativeL1(const std::vector<glm::vec3>& gpu, const std::vector<glm::vec3>& ref) {
    float maxRef = 0.0f;
    for (const auto& v : ref) maxRef = std::max(maxRef, luminance(v));
    double err = 0.0, sum = 0.0;
    for (size_t i = 0; i < ref.size(); ++i) {
        if (luminance(ref[i]) < 0.02f * maxRef) continue;
        err += std::abs(double(luminance(gpu[i])) - luminance(ref[i]));
        sum += luminance(ref[i]);
    }
    return sum > 0.0 ? err / sum : 1e9;
}

// Bound from measurement (docs/caustics.md, "Measured"): at 16 rays per texel of a 64x64 map the
// error was measured at kMeasuredL1At16 against a 4M-photon reference; the bound leaves 50 % margin
// for other seeds and drivers.
constexpr double kMeasuredL1At16 = 0.0495;   // measured 2026-11 on lavapipe (1: 0.19, 4: 0.098)
constexpr double kBoundAt16 = 1.5 * kMeasuredL1At16;

TEST_F(CausticReference, FirstTypeMatchesTheCpuReferenceAndConvergesWithRaysPerTexel) {
    scene::Scene scene = sphereScene();
    scene::Camera cam = sphereCamera();
    reference::ReferenceOptions o;
    o.width = o.height = kSize;
    o.photonsPerLight = 4'000'000;
    o.maxDepth = 4;
    auto ref = reference::renderCausticsReference(scene, cam, o);
    ASSERT_TRUE(ref) << ref.message();
    std::vector<double> errors;
    for (float rays : {1.0f, 4.0f, 16.0f}) {
        CausticsSettings s;
        s.mapResolution = 64;
        s.raysPerTexel = rays;
        s.filter = false;
        s.secondType = false;
        s.russianRoulette = false;
        s.maxStoredHits = 1u << 17;
        auto run = runCaustics(*device, scene, cam, kSize, kSize, s);
        ASSERT_TRUE(run) << run.message();
        errors.push_back(relativeL1(run.value().firstType, ref.value().pixels));
        std::printf("[ measured ] rays per texel %.0f: relative L1 %.4f\n", rays, errors.back());
    }
    EXPECT_LT(errors[1], errors[0]);
    EXPECT_LT(errors[2], errors[1]);
    EXPECT_LT(errors[2], kBoundAt16);
}

// Relative L1 error sum|gpu - ref| / sum(ref) of luminance over the pixels where the reference is
// above `threshold` (cd/m^2).
double relativeL1Above(const std::vector<glm::vec3>& gpu, const std::vector<glm::vec3>& ref, float threshold,
                       uint32_t* count = nullptr) {
    double err = 0.0, sum = 0.0;
    uint32_t n = 0;
    for (size_t i = 0; i < ref.size(); ++i) {
        if (luminance(ref[i]) < threshold) continue;
        err += std::abs(double(luminance(gpu[i])) - luminance(ref[i]));
        sum += luminance(ref[i]);
        ++n;
    }
    if (count) *count = n;
    return sum > 0.0 ? err / sum : 1e9;
}

constexpr uint32_t kTableWidth = 128, kTableHeight = 96;

CausticsSettings tableSettings(float rays, uint32_t seed) {
    CausticsSettings s;
    s.mapResolution = 128;
    s.raysPerTexel = rays;
    s.maxSpecularDepth = 4;
    s.filter = false;
    s.secondType = false;   // the reference renders the first type only
    s.russianRoulette = false;
    s.maxStoredHits = 1u << 16;
    s.seed = seed;
    return s;
}

// Caustic pixels: reference luminance >= 0.05 cd/m^2 (406 of 12288 pixels on the textured table).
// Noise measured on lavapipe (2026-11) at this threshold: reference vs reference (seeds 0/1, 2M photons
// per light) 0.024; GPU vs GPU at 16 rays/texel (seeds 1/2) 0.126. For independent noise the expected
// GPU-vs-reference error is sqrt(0.126^2 / 2 + 0.024^2 / 2) = 0.091; the bound is 1.5x that.
// Measured GPU vs reference: 0.38 / 0.20 / 0.121 at 1 / 4 / 16 rays per texel (seed 2 at 16: 0.122),
// about 1.3x the noise estimate: a small bias remains (see the closing note of the caustics work).
constexpr float kTableCausticThreshold = 0.05f;
constexpr double kTableNoiseL1At16 = 0.091;
constexpr double kTableBoundAt16 = 1.5 * kTableNoiseL1At16;

TEST_F(CausticReference, BuiltinTableFirstTypeMatchesTheCpuReferenceAndConvergesWithRaysPerTexel) {
    scene::Scene scene = scene::makeBuiltinScene("builtin");
    const scene::Camera cam = scene.cameras.at(0);
    reference::ReferenceOptions o;
    o.width = kTableWidth;
    o.height = kTableHeight;
    o.photonsPerLight = 2'000'000;
    o.maxDepth = 4;
    auto ref = reference::renderCausticsReference(scene, cam, o);
    ASSERT_TRUE(ref) << ref.message();
    std::vector<double> errors;
    for (float rays : {1.0f, 4.0f, 16.0f}) {
        auto run = runCaustics(*device, scene, cam, kTableWidth, kTableHeight, tableSettings(rays, 1));
        ASSERT_TRUE(run) << run.message();
        uint32_t pixels = 0;
        errors.push_back(relativeL1Above(run.value().firstType, ref.value().pixels, kTableCausticThreshold, &pixels));
        ASSERT_GT(pixels, 200u) << "too few caustic pixels for a meaningful comparison";
        std::printf("[ measured ] built-in table, rays per texel %.0f: relative L1 %.4f over %u caustic pixels\n", rays,
                    errors.back(), pixels);
    }
    EXPECT_LT(errors[1], errors[0]);
    EXPECT_LT(errors[2], errors[1]);
    EXPECT_LT(errors[2], kTableBoundAt16);
}

// The built-in table scene's third light aims away from every specular object: it gets no map and
// no ray, while the two caustic lights do.
TEST_F(CausticReference, LightsWithoutSpecularObjectsInTheirFrustumDispatchNoRays) {
    auto scene = scene::makeBuiltin("builtin:table");
    ASSERT_TRUE(scene) << scene.message();
    ASSERT_EQ(scene.value().lights.size(), 3u);
    CausticsSettings s;
    s.mapResolution = 32;
    s.filter = false;
    s.secondType = false;
    s.maxStoredHits = 1u << 14;
    auto run = runCaustics(*device, scene.value(), scene.value().cameras.at(0), 32, 32, s);
    ASSERT_TRUE(run) << run.message();
    const CausticRun& r = run.value();
    ASSERT_EQ(r.plan.skippedLights.size(), 1u);
    EXPECT_EQ(r.plan.skippedLights[0], 2u);
    EXPECT_EQ(r.plan.maps.size(), 2u);
    EXPECT_GT(r.raysOfLight(0), 0u);
    EXPECT_GT(r.raysOfLight(1), 0u);
    EXPECT_EQ(r.raysOfLight(2), 0u);
}

}  // namespace
}  // namespace caustics::test
