// A glass sphere that moves under a still camera, filter on (docs/caustics.md "Moving casters"): the
// caustic history follows the caster (CausticsSettings::filterCasterMotion), so the filtered frame is
// both clean and current. The host moves the sphere through the scene it handed to CausticsModule.
// Images are luminance; relative L1 = sum |l - l_ref| / sum l_ref; the peak is the 3x3 mean at the
// reference's brightest 3x3.
#include <gtest/gtest.h>

#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "../caustics/filter_image_metrics.h"
#include "caustics/scene/gpu_scene.h"
#include "gpu_test.h"
#include "module_frames.h"
#include "spot_sphere_scene.h"

namespace caustics::test {
namespace {

constexpr uint32_t kSize = 96;
constexpr uint32_t kFrames = 16;
// 0.5 m/s at 60 frames per second (the case): 8.3 mm per frame, 0.125 m over the 16 frames;
// the focal spot moves ~1.3 px per frame in this view.
constexpr float kStepMetres = 0.5f / 60.0f;

class MovingCasterFilter : public GpuTest {};

CausticsSettings movingSettings(bool casterMotion) {
    CausticsSettings s;
    s.mapResolution = 128;
    s.raysPerTexel = 1.0f;
    s.secondType = false;
    s.maxStoredHits = 1u << 10;
    s.filter = true;
    s.filterCasterMotion = casterMotion;
    s.aov = CausticsAov::Caustics;
    return s;
}

// The sphere's pose in frame n of a run that ends at x = 0.05 m.
glm::mat4 sphereAt(const glm::mat4& rest, float n) {
    const float x = 0.05f - kStepMetres * (float(kFrames - 1) - n);
    return glm::translate(glm::mat4(1.0f), glm::vec3(x, 0.0f, 0.0f)) * rest;
}

// The last of kFrames frames of the module (caustics output) with the sphere at sphereAt(n), or held
// at the last pose when `still`.
std::vector<glm::vec3> lastFrame(const rhi::DeviceHandle& device, const CausticsSettings& settings, bool still) {
    scene::Scene scene = spotSphereScene();
    const uint32_t sphere = sphereInstance(scene);
    const glm::mat4 rest = scene.instances[sphere].transform;
    auto gpuScene = scene::GpuScene::create(*device, scene);
    EXPECT_TRUE(gpuScene) << gpuScene.message();
    if (!gpuScene) return {};
    auto module = CausticsModule::create(device, scene, gpuScene.value(), settings);
    EXPECT_TRUE(module) << module.message();
    if (!module) return {};
    const scene::Camera cam = spotSphereCamera();
    auto images = runModuleFrames(*device, *module.value(), kFrames, 2, [&](uint32_t n) {
        scene.instances[sphere].transform = sphereAt(rest, still ? float(kFrames - 1) : float(n));
        return std::vector<ViewRequest>{viewOf(cam, kSize, ModuleOutput::Caustics)};
    });
    EXPECT_TRUE(images) << images.message();
    if (!images) return {};
    return images.value().back()[0].pixels;
}

// Bounds (the issue's): with caster motion the moving frame's L1 to the converged reference is at most
// 0.8x that of the filter that follows the receiver only, and its 3x3 peak within 10 % of the still
// sphere's. Measured (lavapipe, 2026-12-02, "[ measured ]" lines), seeds 1 / 2: L1 0.233 / 0.239 against
// 0.658 / 0.677 (0.35x), peak ratio to the still case 0.931 / 0.925; the test runs seed 1.
TEST_F(MovingCasterFilter, HistoryFollowsAMovingGlassSphere) {
    CausticsSettings reference = movingSettings(true);
    reference.filter = false;
    reference.raysPerTexel = 128.0f;   // 2.1 M photons: the converged caustic at the last pose
    reference.seed = 1000;
    const std::vector<glm::vec3> ref = lastFrame(device, reference, true);
    ASSERT_EQ(ref.size(), size_t(kSize) * kSize);
    const PeakLocation spot = brightest3x3(ref, kSize, kSize);
    ASSERT_GT(spot.value, 0.0) << "no caustic in view";
    const std::vector<glm::vec3> followed = lastFrame(device, movingSettings(true), false);
    const std::vector<glm::vec3> receiverOnly = lastFrame(device, movingSettings(false), false);
    const std::vector<glm::vec3> still = lastFrame(device, movingSettings(true), true);
    ASSERT_EQ(followed.size(), ref.size());
    ASSERT_EQ(receiverOnly.size(), ref.size());
    ASSERT_EQ(still.size(), ref.size());
    const double l1Followed = relativeL1(followed, ref), l1ReceiverOnly = relativeL1(receiverOnly, ref);
    const double l1Still = relativeL1(still, ref);
    const double peakFollowed = mean3x3(followed, kSize, kSize, spot.x, spot.y) / spot.value;
    const double peakReceiverOnly = mean3x3(receiverOnly, kSize, kSize, spot.x, spot.y) / spot.value;
    const double peakStill = mean3x3(still, kSize, kSize, spot.x, spot.y) / spot.value;
    std::printf("[ measured ] moving, caster motion    L1 %.4f  peak %.4f  energy %.4f\n", l1Followed, peakFollowed,
                energy(followed) / energy(ref));
    std::printf("[ measured ] moving, receiver only    L1 %.4f  peak %.4f  energy %.4f\n", l1ReceiverOnly, peakReceiverOnly,
                energy(receiverOnly) / energy(ref));
    std::printf("[ measured ] still                    L1 %.4f  peak %.4f  energy %.4f\n", l1Still, peakStill,
                energy(still) / energy(ref));
    dumpLuminance("moving_caster_reference", ref, kSize, kSize, spot.value);
    dumpLuminance("moving_caster_followed", followed, kSize, kSize, spot.value);
    dumpLuminance("moving_caster_receiver_only", receiverOnly, kSize, kSize, spot.value);
    EXPECT_LE(l1Followed, 0.8 * l1ReceiverOnly);
    EXPECT_NEAR(peakFollowed / peakStill, 1.0, 0.1);
}

}  // namespace
}  // namespace caustics::test
