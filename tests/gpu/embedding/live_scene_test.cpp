// A live scene (docs/embedding.md "A live scene"): the host moves the glass sphere and turns the spot
// light every frame through the scene it handed to CausticsModule; every frame's first-type caustic
// must match the CPU reference light tracer (engine/reference) for that frame's transforms.
#include <gtest/gtest.h>

#include <cstdio>

#include "caustics/reference/reference_tracer.h"
#include "caustics/scene/gpu_scene.h"
#include "gpu_test.h"
#include "module_frames.h"
#include "spot_sphere_scene.h"

namespace caustics::test {
namespace {

constexpr uint32_t kSize = 64;
constexpr uint32_t kFrames = 8;

class LiveScene : public GpuTest {};

CausticsSettings firstTypeSettings() {
    CausticsSettings s;
    s.mapResolution = 96;
    s.raysPerTexel = 8.0f;
    s.filter = false;
    s.secondType = false;
    s.russianRoulette = false;
    s.maxStoredHits = 1u << 12;
    s.aov = CausticsAov::FirstType;   // the module exports the first-type image for that AOV only
    return s;
}

// Bounds from measurement (lavapipe, 2026-11-30; the "[ measured ]" lines of this test): the peak of
// the GPU image is at most 0.01 px from the reference's in all 8 frames (same emission maps and
// estimator; the 50 %-of-peak centroid averages the noise), and the energy ratio GPU / reference is
// 0.974..0.985 (a 2 % low bias, docs/caustics.md; seeds of one run spread it by +-0.006).
// Bounds: peak 0.5 px, 50x the measurement and a seventh of the 3.5 px the focus moves per frame (a
// one-frame-stale transform or light misses by 3+ px); energy |ratio - 1| < 2 x 0.026 (largest
// measured deviation).
constexpr float kPeakBoundPx = 0.5f;
constexpr double kMeasuredEnergy = 0.026;
constexpr double kEnergyBound = 2.0 * kMeasuredEnergy;

TEST_F(LiveScene, MovingGlassSphereAndTurningSpotMatchTheCpuReferenceEveryFrame) {
    scene::Scene scene = spotSphereScene();
    const glm::mat4 rest = scene.instances[sphereInstance(scene)].transform;
    const scene::Camera cam = spotSphereCamera();
    auto gpuScene = scene::GpuScene::create(*device, scene);
    ASSERT_TRUE(gpuScene) << gpuScene.message();
    auto module = CausticsModule::create(device, scene, gpuScene.value(), firstTypeSettings());
    ASSERT_TRUE(module) << module.message();

    std::vector<FrameImage> references;
    std::vector<glm::vec2> sphereScreen;
    auto images = runModuleFrames(*device, *module.value(), kFrames, 2, [&](uint32_t n) {
        poseSpotSphere(scene, float(n) / float(kFrames - 1), rest);
        reference::ReferenceOptions o;
        o.width = o.height = kSize;
        o.photonsPerLight = 400'000;
        o.maxDepth = 4;
        o.seed = 100 + n;
        auto ref = reference::renderCausticsReference(scene, cam, o);
        EXPECT_TRUE(ref) << ref.message();
        references.push_back(FrameImage{kSize, kSize, ref ? ref.value().pixels : std::vector<glm::vec3>()});
        return std::vector<ViewRequest>{viewOf(cam, kSize, ModuleOutput::FirstType)};
    });
    ASSERT_TRUE(images) << images.message();
    ASSERT_EQ(references.size(), size_t(kFrames));

    glm::vec2 firstPeak(0.0f), lastPeak(0.0f);
    for (uint32_t n = 0; n < kFrames; ++n) {
        const FrameImage& gpu = images.value()[n][0];
        const FrameImage& ref = references[n];
        const glm::vec2 gpuPeak = peakCentroid(gpu.pixels, kSize, kSize);
        const glm::vec2 refPeak = peakCentroid(ref.pixels, kSize, kSize);
        const double energy = totalLuminance(gpu) / totalLuminance(ref);
        std::printf("[ measured ] frame %u: peak gpu (%.2f, %.2f) ref (%.2f, %.2f) offset %.2f px, energy ratio %.4f\n", n,
                    gpuPeak.x, gpuPeak.y, refPeak.x, refPeak.y, glm::length(gpuPeak - refPeak), energy);
        ASSERT_GE(refPeak.x, 0.0f) << "frame " << n << ": the reference has no caustic";
        EXPECT_LT(glm::length(gpuPeak - refPeak), kPeakBoundPx) << "frame " << n;
        EXPECT_NEAR(energy, 1.0, kEnergyBound) << "frame " << n;
        if (n == 0) firstPeak = refPeak;
        lastPeak = refPeak;
    }
    // The path must actually move the caustic (measured: 24 px), or the per-frame comparison proves nothing.
    EXPECT_GT(glm::length(lastPeak - firstPeak), 10.0f);
}

// A light added mid-run and one removed: the GPU reads this frame's light table, not the first one's.
TEST_F(LiveScene, LightsAddedAndRemovedBetweenFramesChangeTheCausticAtOnce) {
    scene::Scene scene = spotSphereScene();
    const scene::Camera cam = spotSphereCamera();
    auto gpuScene = scene::GpuScene::create(*device, scene);
    ASSERT_TRUE(gpuScene) << gpuScene.message();
    auto module = CausticsModule::create(device, scene, gpuScene.value(), firstTypeSettings());
    ASSERT_TRUE(module) << module.message();
    const scene::Light original = scene.lights[0];
    auto images = runModuleFrames(*device, *module.value(), 3, 1, [&](uint32_t n) {
        if (n == 1) {   // a second, identical spot: twice the flux through the sphere
            scene.lights.push_back(original);
            scene.lights.back().name = "second spot";
        }
        if (n == 2) scene.lights = {original};
        return std::vector<ViewRequest>{viewOf(cam, kSize, ModuleOutput::FirstType)};
    });
    ASSERT_TRUE(images) << images.message();
    const double one = totalLuminance(images.value()[0][0]);
    const double two = totalLuminance(images.value()[1][0]);
    const double back = totalLuminance(images.value()[2][0]);
    std::printf("[ measured ] energy one light %.4f, two %.4f (ratio %.4f), one again %.4f\n", one, two, two / one, back);
    // Measured: 2 lights / 1 light = 1.992, 1 light again / 1 light = 0.9975 (different frame seeds).
    // Bound: the energy bound above (per-frame noise and bias), doubled for the two-light sum; a
    // stale light table gives 1.0 or 0.5 instead.
    EXPECT_NEAR(two / one, 2.0, 2.0 * kEnergyBound);
    EXPECT_NEAR(back / one, 1.0, kEnergyBound);
}

}  // namespace
}  // namespace caustics::test
