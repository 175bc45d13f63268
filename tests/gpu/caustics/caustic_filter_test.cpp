// The caustic filter (docs/caustics.md "Filter"; SVGF-like) against converged renders of the same
// renderer: a glass ball's focal spot and the metal ring's cardioid close-up, 128x128, fixed seeds.
// Every comparison uses luminance: relative L1 = sum |l - l_ref| / sum l_ref over the image, the 3x3
// peak = 3x3 mean at the reference's brightest 3x3 location, energy = sum of l.
// Set CAUSTICS_FILTER_IMAGES=<folder> to get the images as PGM (and raw float luminance) files.
// Bounds are the task's (issue 10); the measured values are printed as "[ measured ]" lines. Noise they sit
// on (lavapipe, 2026-12-01): the reference itself, seed 2000 vs seed 1000, differs by L1 0.074 (ball) and
// 0.042 (ring) with peak and energy within 0.6 %; the 1-ray frame's energy is within 0.4 % of the reference
// for these seeds, so the 3 % energy bound measures the filter, not the sampling.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <map>
#include <string>

#include "caustic_harness.h"
#include "filter_image_metrics.h"
#include "gpu_test.h"
#include "caustics/scene/builtin_scenes.h"

namespace caustics::test {
namespace {

constexpr uint32_t kSize = 96;

struct FilterScene {
    std::string name;
    scene::Scene scene;
    scene::Camera camera;
    scene::Camera panned;      // the camera turned by about 5 degrees (pan test)
    CausticsSettings settings; // 1 ray per texel, filter on with its defaults
    // The converged image: one frame at this many rays per texel, filter off (2.4 M rays for the ball,
    // 9.4 M for the ring: at 64 rays per texel the ring's reference differed from another seed's by L1
    // 0.087, a third of the one-frame L1 under test; at 256 by 0.042).
    float referenceRays = 0.0f;
};

CausticsSettings baseSettings(uint32_t mapResolution) {
    CausticsSettings s;
    s.mapResolution = mapResolution;
    s.raysPerTexel = 1.0f;
    s.secondType = false;      // the filter sees first + second type alike; the first type is cheaper to converge
    s.maxStoredHits = 1u << 10;
    s.filter = true;
    return s;
}

// Glass ball (n = 1.5, R = 0.5) under a sun 31 degrees off vertical, placed so that its paraxial focus
// f = nR / (2(n - 1)) = 0.75 from the centre along the light lies on the floor, beside the ball.
FilterScene glassBallFocalSpot() {
    scene::AnalyticSceneDesc d;
    d.radius = 0.5f;
    d.tessellation = 96;
    d.lightDirection = glm::normalize(glm::vec3(0.6f, -1.0f, 0.0f));
    d.height = 0.75f * -d.lightDirection.y;
    FilterScene s{"ball", scene::makeGlassSphereScene(d), {}, {}, baseSettings(96), 256.0f};
    s.camera.eye = {1.6f, 1.0f, 1.2f};
    s.camera.target = {0.35f, 0.0f, 0.0f};
    s.camera.verticalFovRadians = glm::radians(30.0f);
    s.panned = s.camera;
    s.panned.target = {0.45f, 0.0f, -0.15f};
    return s;
}

// Polished ring under light at 30 degrees elevation; the camera looks down at the cardioid inside.
FilterScene ringCloseUp() {
    FilterScene s{"ring", scene::makeMetalRingScene(), {}, {}, baseSettings(192), 256.0f};
    s.camera.eye = {-0.1f, 1.1f, 0.5f};
    s.camera.target = {-0.15f, 0.0f, 0.0f};
    s.camera.verticalFovRadians = glm::radians(35.0f);
    s.panned = s.camera;
    s.panned.target = {-0.05f, 0.0f, -0.05f};
    return s;
}

class CausticFilter : public GpuTest {
protected:
    // One frame, filter off (the unfiltered estimate), at `rays` per texel.
    std::vector<glm::vec3> unfiltered(const FilterScene& s, const scene::Camera& camera, float rays, uint32_t seed) {
        CausticsSettings settings = s.settings;
        settings.filter = false;
        settings.raysPerTexel = rays;
        settings.seed = seed;
        auto run = runCaustics(*device, s.scene, camera, kSize, kSize, settings);
        EXPECT_TRUE(run) << run.message();
        return run ? run.value().radiance : std::vector<glm::vec3>(size_t(kSize) * kSize);
    }
    // The converged image, computed once per scene and view for the whole test program.
    const std::vector<glm::vec3>& reference(const FilterScene& s, const scene::Camera& camera, const char* view) {
        static std::map<std::string, std::vector<glm::vec3>> cache;
        const std::string key = s.name + "." + view;
        auto it = cache.find(key);
        if (it == cache.end()) it = cache.emplace(key, unfiltered(s, camera, s.referenceRays, 1000)).first;
        return it->second;
    }
    // Frames with the filter on, one per camera; the last frame's filtered and unfiltered images.
    struct Filtered {
        std::vector<glm::vec3> filtered, unfiltered;
    };
    Filtered filtered(const FilterScene& s, std::span<const scene::Camera> cameras) {
        auto run = runCaustics(*device, s.scene, cameras, kSize, kSize, s.settings);
        EXPECT_TRUE(run) << run.message();
        Filtered f{std::vector<glm::vec3>(size_t(kSize) * kSize), std::vector<glm::vec3>(size_t(kSize) * kSize)};
        if (!run) return f;
        f.filtered = run.value().radiance;
        for (size_t i = 0; i < f.unfiltered.size(); ++i) f.unfiltered[i] = run.value().firstType[i] + run.value().secondType[i];
        return f;
    }
};

struct Comparison {
    double l1 = 0.0, peak = 0.0, energy = 0.0;   // L1 relative to the reference's sum, ratios to the reference
};

Comparison compare(const std::vector<glm::vec3>& img, const std::vector<glm::vec3>& ref) {
    PeakLocation p = brightest3x3(ref, kSize, kSize);
    return {relativeL1(img, ref), mean3x3(img, kSize, kSize, p.x, p.y) / p.value, energy(img) / energy(ref)};
}

void print(const std::string& what, const Comparison& c) {
    std::printf("[ measured ] %-34s L1 %.4f  peak %.4f  energy %.4f\n", what.c_str(), c.l1, c.peak, c.energy);
}

double white(const std::vector<glm::vec3>& ref) { return brightest3x3(ref, kSize, kSize).value; }

// One frame at 1 ray per texel: the filter must beat 4x the rays without filtering (relative L1), keep
// the focal spot / cusp (3x3 peak within 20 %) and the energy (within 3 %). Measured over the seeds 1..6
// of the filtered frame and the 4-ray image (2026-12-01, the test runs seed 1):
//   ring: filtered L1 0.218-0.230 (seed 1: 0.2231) vs 4 rays 0.237-0.246 (0.2370); filtered 3x3 peak
//         0.84-1.01 (0.92; the unfiltered 1-ray frame's own peak varies 0.91-1.08), energy within 0.6 %;
//   ball: filtered L1 0.164-0.177 (0.1708) vs 4 rays 0.354-0.362 (0.3610); peak 0.93-0.99 (0.97).
// Before the Gaussian luminance weight and the robust shot-noise variance (docs/caustics.md "Filter") the
// ring failed: L1 0.278 against 0.242, peak 0.82.
TEST_F(CausticFilter, OneFrameAtOneRayBeatsFourRaysUnfilteredAndKeepsThePeakAndEnergy) {
    for (const FilterScene& s : {glassBallFocalSpot(), ringCloseUp()}) {
        SCOPED_TRACE(s.name);
        const std::vector<glm::vec3>& ref = reference(s, s.camera, "main");
        const scene::Camera cams[] = {s.camera};
        Filtered one = filtered(s, cams);
        std::vector<glm::vec3> four = unfiltered(s, s.camera, 4.0f, 1);
        Comparison f = compare(one.filtered, ref), u1 = compare(one.unfiltered, ref), u4 = compare(four, ref);
        print(s.name + " 1 frame filtered", f);
        print(s.name + " 1 frame unfiltered (1 ray)", u1);
        print(s.name + " unfiltered 4 rays", u4);
        print(s.name + " reference (seed 2) vs reference", compare(unfiltered(s, s.camera, s.referenceRays, 2000), ref));
        dumpLuminance(s.name + "_reference", ref, kSize, kSize, white(ref));
        dumpLuminance(s.name + "_1frame_filtered", one.filtered, kSize, kSize, white(ref));
        dumpLuminance(s.name + "_1frame_unfiltered", one.unfiltered, kSize, kSize, white(ref));
        dumpLuminance(s.name + "_unfiltered_4rays", four, kSize, kSize, white(ref));
        EXPECT_LT(f.l1, u4.l1);
        EXPECT_NEAR(f.peak, 1.0, 0.2);
        EXPECT_NEAR(f.energy, 1.0, 0.03);
        // The a-trous passes hand out each pixel's radiance exactly (source normalisation): the filtered
        // frame has the unfiltered frame's energy up to float rounding (measured equal to 4 digits).
        EXPECT_NEAR(f.energy / u1.energy, 1.0, 1e-3);
    }
}

// Iterations past the third (steps 8 to 128, whose taps leave the tile's 3x3 neighbourhood: the a-trous
// passes then find each tap's pool tile by its offset, passes/caustic_filter/shaders/atrous_thread.h)
// still hand out each pixel's radiance exactly and land it where it belongs: relative L1 to the reference
// within 3 % of three iterations' (measured 2026-12-03, lavapipe: 0.1711 / 0.1712 / 0.1711 for 4 / 5 / 8
// against 0.1713, the image 1.9-2.2 % from three iterations'; the 3 % is the seed-to-seed spread of the
// one-frame L1, 0.164-0.177, in relative terms a third of it). Ball, one frame, seed 1.
TEST_F(CausticFilter, EveryIterationCountUpToTheMaximumKeepsTheEnergy) {
    const FilterScene s = glassBallFocalSpot();
    const std::vector<glm::vec3>& ref = reference(s, s.camera, "main");
    const scene::Camera cams[] = {s.camera};
    const Filtered three = filtered(s, cams);
    const double threeL1 = compare(three.filtered, ref).l1;
    for (uint32_t iterations : {4u, 5u, CausticsSettings::kMaxAtrousIterations}) {
        SCOPED_TRACE(iterations);
        FilterScene wide = s;
        wide.settings.atrousIterations = iterations;
        const Filtered f = filtered(wide, cams);
        const Comparison c = compare(f.filtered, ref), u = compare(f.unfiltered, ref);
        const double change = relativeL1(f.filtered, three.filtered);
        print(s.name + " " + std::to_string(iterations) + " iterations", c);
        std::printf("[ measured ] %u iterations: relative L1 to 3 iterations %.4f\n", iterations, change);
        EXPECT_NEAR(c.energy / u.energy, 1.0, 1e-3);
        EXPECT_NEAR(c.peak, 1.0, 0.2);
        EXPECT_LT(c.l1, 1.03 * threeL1);
    }
}

// A still camera for 32 frames (= the default history cap): the temporal average of 32 frames at 1 ray
// per texel, spatially filtered, must beat 16 rays unfiltered and keep the peak within 10 %. Measured
// (2026-12-01, filter seeds 1..6): ring L1 0.105-0.112 (seed 1: 0.1124) vs 0.1209, peak 0.99-1.01; ball
// 0.096-0.099 (0.0993) vs 0.2094, peak within 0.5 %. (The ring's temporal mean alone, atrousIterations 0,
// reaches 0.092: at 32 frames the spatial passes cost the ring detail; docs/caustics.md "Filter".)
TEST_F(CausticFilter, StillCameraConvergesToTheUnfilteredMean) {
    for (const FilterScene& s : {glassBallFocalSpot(), ringCloseUp()}) {
        SCOPED_TRACE(s.name);
        const std::vector<glm::vec3>& ref = reference(s, s.camera, "main");
        const std::vector<scene::Camera> cams(32, s.camera);
        Filtered many = filtered(s, cams);
        Comparison f = compare(many.filtered, ref), u16 = compare(unfiltered(s, s.camera, 16.0f, 1), ref);
        print(s.name + " 32 frames filtered", f);
        print(s.name + " unfiltered 16 rays", u16);
        dumpLuminance(s.name + "_32frames_filtered", many.filtered, kSize, kSize, white(ref));
        EXPECT_LT(f.l1, u16.l1);
        EXPECT_NEAR(f.peak, 1.0, 0.1);
        EXPECT_NEAR(f.energy, 1.0, 0.03);
    }
}

// 8 frames at one view, then the camera turns by about 5 degrees: 4 frames later the error must be
// within 1.5x that of 4 frames started fresh at the new view (a trail of the old view would not be).
TEST_F(CausticFilter, CameraPanLeavesNoTrail) {
    for (const FilterScene& s : {glassBallFocalSpot(), ringCloseUp()}) {
        SCOPED_TRACE(s.name);
        const std::vector<glm::vec3>& ref = reference(s, s.panned, "panned");
        std::vector<scene::Camera> panned(8, s.camera);
        panned.insert(panned.end(), 4, s.panned);
        const std::vector<scene::Camera> fresh(4, s.panned);
        const std::vector<glm::vec3> afterPan = filtered(s, panned).filtered, fromFresh = filtered(s, fresh).filtered;
        Comparison p = compare(afterPan, ref), f = compare(fromFresh, ref);
        dumpLuminance(s.name + "_panned_reference", ref, kSize, kSize, white(ref));
        dumpLuminance(s.name + "_panned_after_pan", afterPan, kSize, kSize, white(ref));
        dumpLuminance(s.name + "_panned_fresh", fromFresh, kSize, kSize, white(ref));
        print(s.name + " 8 frames + pan + 4 frames", p);
        print(s.name + " 4 frames fresh at the new view", f);
        EXPECT_LT(p.l1, 1.5 * f.l1);
    }
}

// The camera stays, the sun turns by 15 degrees about the vertical (the focal spot moves ~9 px): 8 frames
// under the old sun, then 4 under the new one. The history follows the camera only, so without the
// photon-count test (historyRejected in temporal.comp) 8/12 of the old spot would still show; the error
// must be within 1.5x that of 4 frames started fresh under the new sun, as for a camera pan.
TEST_F(CausticFilter, MovingLightLeavesNoTrail) {
    const FilterScene s = glassBallFocalSpot();
    const float turn = glm::radians(15.0f);
    std::vector<scene::Light> before = s.scene.lights, after = s.scene.lights;
    for (scene::Light& l : after) {
        const glm::vec3 d = l.direction;
        l.direction = {std::cos(turn) * d.x + std::sin(turn) * d.z, d.y, -std::sin(turn) * d.x + std::cos(turn) * d.z};
    }
    scene::Scene turned = s.scene;
    turned.lights = after;
    CausticsSettings refSettings = s.settings;
    refSettings.filter = false;
    refSettings.raysPerTexel = s.referenceRays;
    refSettings.seed = 1000;
    auto refRun = runCaustics(*device, turned, s.camera, kSize, kSize, refSettings);
    ASSERT_TRUE(refRun) << refRun.message();
    const std::vector<glm::vec3>& ref = refRun.value().radiance;
    const PeakLocation oldSpot = brightest3x3(reference(s, s.camera, "main"), kSize, kSize);
    const PeakLocation newSpot = brightest3x3(ref, kSize, kSize);
    ASSERT_GT(std::hypot(double(newSpot.x - oldSpot.x), double(newSpot.y - oldSpot.y)), 5.0)
        << "the focal spot must move for this test to mean anything";

    auto run = [&](uint32_t framesBefore) {
        std::vector<std::vector<scene::Light>> lights(framesBefore, before);
        lights.insert(lights.end(), 4, after);
        const std::vector<scene::Camera> cameras(lights.size(), s.camera);
        auto r = runCaustics(*device, s.scene, cameras, kSize, kSize, s.settings, 3, lights);
        EXPECT_TRUE(r) << r.message();
        return r ? r.value().radiance : std::vector<glm::vec3>(size_t(kSize) * kSize);
    };
    const std::vector<glm::vec3> afterTurn = run(8), fromFresh = run(0);
    Comparison t = compare(afterTurn, ref), f = compare(fromFresh, ref);
    dumpLuminance("ball_light_turned_reference", ref, kSize, kSize, white(ref));
    dumpLuminance("ball_light_turned_after_turn", afterTurn, kSize, kSize, white(ref));
    dumpLuminance("ball_light_turned_fresh", fromFresh, kSize, kSize, white(ref));
    print("ball 8 frames + sun turn + 4 frames", t);
    print("ball 4 frames fresh under the new sun", f);
    EXPECT_LT(t.l1, 1.5 * f.l1);
    EXPECT_NEAR(t.peak, 1.0, 0.2);
}

std::string errorOf(const Status& s) { return s ? std::string() : s.message(); }

// Absurd filter settings are refused naming the field.
TEST(CausticFilterSettings, AbsurdValuesAreRefusedNamingTheField) {
    CausticsSettings s;
    s.filterMaxHistory = 0;
    EXPECT_NE(errorOf(s.validate()).find("filterMaxHistory"), std::string::npos);
    s = {};
    s.filterLuminanceSigma = std::nanf("");
    EXPECT_NE(errorOf(s.validate()).find("filterLuminanceSigma"), std::string::npos);
    s = {};
    s.atrousIterations = CausticsSettings::kMaxAtrousIterations + 1;
    EXPECT_NE(errorOf(s.validate()).find("atrousIterations"), std::string::npos);
    s = {};
    s.filterPoolTiles = CausticsSettings::kMaxFilterPoolTiles + 1;
    EXPECT_NE(errorOf(s.validate()).find("filterPoolTiles"), std::string::npos);
    EXPECT_TRUE(CausticsSettings{}.validate());
}

}  // namespace
}  // namespace caustics::test
