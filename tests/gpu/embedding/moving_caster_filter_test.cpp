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

// The kFrames frames of the module (its caustics output as seen by `cam`) with the sphere at
// sphereAt(n), or held at the last pose when `still`.
std::vector<std::vector<glm::vec3>> framesOf(const rhi::DeviceHandle& device, const CausticsSettings& settings, bool still,
                                             const scene::Camera& cam) {
    scene::Scene scene = spotSphereScene();
    const uint32_t sphere = sphereInstance(scene);
    const glm::mat4 rest = scene.instances[sphere].transform;
    auto gpuScene = scene::GpuScene::create(*device, scene);
    EXPECT_TRUE(gpuScene) << gpuScene.message();
    if (!gpuScene) return {};
    auto module = CausticsModule::create(device, scene, gpuScene.value(), settings);
    EXPECT_TRUE(module) << module.message();
    if (!module) return {};
    auto images = runModuleFrames(*device, *module.value(), kFrames, 2, [&](uint32_t n) {
        scene.instances[sphere].transform = sphereAt(rest, still ? float(kFrames - 1) : float(n));
        return std::vector<ViewRequest>{viewOf(cam, kSize, ModuleOutput::Caustics)};
    });
    EXPECT_TRUE(images) << images.message();
    if (!images) return {};
    std::vector<std::vector<glm::vec3>> frames;
    for (const auto& frame : images.value()) frames.push_back(frame[0].pixels);
    return frames;
}

std::vector<glm::vec3> lastFrame(const rhi::DeviceHandle& device, const CausticsSettings& settings, bool still,
                                 const scene::Camera& cam = spotSphereCamera()) {
    auto frames = framesOf(device, settings, still, cam);
    return frames.empty() ? std::vector<glm::vec3>() : frames.back();
}

// The mean of the frames of a still sphere, unfiltered: every frame jitters the backward pass's pixel
// rays anew, so their mean converges the second type too.
std::vector<glm::vec3> stillMean(const rhi::DeviceHandle& device, const CausticsSettings& settings, const scene::Camera& cam) {
    auto frames = framesOf(device, settings, true, cam);
    if (frames.empty()) return {};
    std::vector<glm::vec3> mean(frames[0].size(), glm::vec3(0.0f));
    for (const auto& f : frames)
        for (size_t i = 0; i < f.size(); ++i) mean[i] += f[i] / float(frames.size());
    return mean;
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

// The second type under a moving glass (issue 18): the camera straight above the sphere looks through it
// at its focal spot, so most of the caustic in view is seen through the glass, and the pixels that show
// the sphere take their history from where that point of the sphere was (the instance's own motion,
// docs/caustics.md "Moving objects"). Reference: the mean of 16 unfiltered frames of the still sphere at
// its last pose, 16 rays per texel each. Bounds as above (the issue's): L1 at most 0.8x that of the filter
// that follows the camera only, peak within 10 % of the still sphere's. Measured (lavapipe, 2026-12-02,
// "[ measured ]" lines), seeds 1 / 2 / 3: L1 0.283 / 0.326 / 0.258 against 0.505 / 0.521 / 0.462 following
// the camera only (0.56x / 0.63x / 0.56x), peak ratio to the still case 1.039 / 0.933 / 1.007; energy
// 1.07 / 1.15 / 1.08 of the reference against 1.26 / 1.29 / 1.20 (the trail); the test runs seed 1.
// Since the temporal pass waits a frame before a rise drops a history on the glass's pixels
// (docs/caustics.md "Moving caustics", 2026-12-05), seed 1: L1 0.229 against 0.406 (0.56x), peak ratio
// 1.022, energy 0.996 against 1.066: part of the extra energy was single photons restarting histories.
// `apart`: the second type filtered on its own guides (filterSecondTypeApart).
void expectSecondTypeFollowsTheMovingGlass(const rhi::DeviceHandle& device, bool apart) {
    scene::Camera above;
    above.eye = {0.0f, 2.4f, 0.25f};
    above.target = {0.0f, 0.0f, 0.0f};
    above.verticalFovRadians = 0.5f;
    above.nearPlane = 0.05f;
    above.farPlane = 20.0f;
    auto settings = [apart](bool motion) {
        CausticsSettings s = movingSettings(motion);
        s.secondType = true;
        s.filterSecondTypeApart = apart;
        s.maxStoredHits = 1u << 16;
        return s;
    };
    CausticsSettings reference = settings(true);
    reference.filter = false;
    reference.raysPerTexel = 16.0f;               // x 16 frames: 256 rays per texel
    reference.maxStoredHits = 1u << 19;           // every photon's hit is gathered (262 k a frame)
    reference.seed = 1000;
    const std::vector<glm::vec3> ref = stillMean(device, reference, above);
    ASSERT_EQ(ref.size(), size_t(kSize) * kSize);
    const PeakLocation spot = brightest3x3(ref, kSize, kSize);
    ASSERT_GT(spot.value, 0.0) << "no caustic in view";
    const std::vector<glm::vec3> followed = lastFrame(device, settings(true), false, above);
    const std::vector<glm::vec3> cameraOnly = lastFrame(device, settings(false), false, above);
    const std::vector<glm::vec3> still = lastFrame(device, settings(true), true, above);
    ASSERT_EQ(followed.size(), ref.size());
    ASSERT_EQ(cameraOnly.size(), ref.size());
    ASSERT_EQ(still.size(), ref.size());
    const double l1Followed = relativeL1(followed, ref), l1CameraOnly = relativeL1(cameraOnly, ref);
    const double peakFollowed = mean3x3(followed, kSize, kSize, spot.x, spot.y) / spot.value;
    const double peakCameraOnly = mean3x3(cameraOnly, kSize, kSize, spot.x, spot.y) / spot.value;
    const double peakStill = mean3x3(still, kSize, kSize, spot.x, spot.y) / spot.value;
    std::printf("[ measured ] through glass%s, object motion  L1 %.4f  peak %.4f  energy %.4f\n", apart ? " (apart)" : "", l1Followed, peakFollowed,
                energy(followed) / energy(ref));
    std::printf("[ measured ] through glass%s, camera only    L1 %.4f  peak %.4f  energy %.4f\n", apart ? " (apart)" : "", l1CameraOnly, peakCameraOnly,
                energy(cameraOnly) / energy(ref));
    std::printf("[ measured ] through glass%s, still          L1 %.4f  peak %.4f  energy %.4f\n", apart ? " (apart)" : "", relativeL1(still, ref), peakStill,
                energy(still) / energy(ref));
    dumpLuminance("moving_glass_reference", ref, kSize, kSize, spot.value);
    dumpLuminance(apart ? "moving_glass_apart_followed" : "moving_glass_followed", followed, kSize, kSize, spot.value);
    dumpLuminance(apart ? "moving_glass_apart_camera_only" : "moving_glass_camera_only", cameraOnly, kSize, kSize, spot.value);
    EXPECT_LE(l1Followed, 0.8 * l1CameraOnly);
    EXPECT_NEAR(peakFollowed / peakStill, 1.0, 0.1);
}

TEST_F(MovingCasterFilter, SecondTypeThroughAMovingGlassKeepsItsHistory) { expectSecondTypeFollowsTheMovingGlass(device, false); }

// The same with the second type filtered on its own guides: the guide's motion is the glass's
// (second_type_guides.h secondTypeGuideThroughMovedGlass). Measured (lavapipe, 2026-12-02), seeds 1 / 2 / 3:
// L1 0.279 / 0.319 / 0.248 against 0.497 / 0.508 / 0.452 following the camera only (0.56x / 0.63x / 0.55x),
// peak ratio to the still case 1.048 / 0.948 / 0.985. With rises confirmed (2026-12-05), seed 1: L1 0.226
// against 0.398 (0.57x), peak ratio 1.018, energy 0.992.
TEST_F(MovingCasterFilter, SecondTypeFilteredApartThroughAMovingGlassKeepsItsHistory) {
    expectSecondTypeFollowsTheMovingGlass(device, true);
}

}  // namespace
}  // namespace caustics::test
