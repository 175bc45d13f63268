// The second type's own filter guides (caustics.secondTypeGuides; docs/caustics.md "Second-type guides")
// against the independent reference's optics (tests/reference/second_type): through a glass pane, each
// guided pixel holds the floor point its camera ray reaches through the pane (depth, normal, id) and
// that point's screen motion between two camera positions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "caustic_harness.h"
#include "caustics/camera_constants.h"
#include "gpu_test.h"
#include "independent_metrics.h"
#include "independent_cases.h"
#include "second_type_estimate.h"
#include "second_type_metrics.h"

namespace caustics::test {
namespace {

class SecondTypeGuides : public GpuTest {};

constexpr uint32_t kSize = 64;
constexpr uint32_t kFloorId = 1;   // the floor is the scene's first instance (emptyCase): id = instance + 1

// A 1 cm pane filling the view of a camera that looks down at the floor, lit from above (the light
// sees the pane, so a map is planned and the second type runs).
IndependentCase paneOverFloor() {
    IndependentCase c = emptyCase("pane over the floor");
    c.camera = lookAt({1.6f, 1.2f, 0.0f}, {0.48f, 0.0f, 0.0f}, 25.0f);
    addPaneInFrontOfCamera(c, 0.15f, 0.15f);
    setDirectional(c, {0.6f, -1.0f, 0.0f}, 1.0f);
    return c;
}

// Texel-centre position of a world point in an image of kSize^2 (the filter's convention).
glm::dvec2 texelOf(const glm::mat4& viewProj, const glm::dvec3& x) {
    glm::dvec4 clip = glm::dmat4(viewProj) * glm::dvec4(x, 1.0);
    return (glm::dvec2(clip) / clip.w * 0.5 + 0.5) * double(kSize) - 0.5;
}

// What the guides of pixel (x, y) may hold: the backward ray is jittered inside the pixel, and a pixel
// whose sample made no sphere takes a neighbour's guides (caustics.secondTypeGuides.fill), so each
// quantity lies between its values at the four corners of the pixel's 3x3 neighbourhood (monotone
// over it for a plane seen through a plane).
struct GuideRange {
    double depthLo = std::numeric_limits<double>::max(), depthHi = -depthLo;
    glm::dvec2 motionLo{depthLo}, motionHi{-depthLo};
    bool onFloor = true;
};

// reach: 1 the 3x3 neighbourhood's corners, 0 the pixel's own.
GuideRange expectedRange(const IndependentCase& c, uint32_t x, uint32_t y, const CameraConstants& now, const glm::mat4& before,
                         int reach) {
    GuideRange r;
    const glm::dvec3 eye(c.camera.eye), forward = glm::normalize(glm::dvec3(c.camera.target - c.camera.eye));
    for (int corner = 0; corner < 4; ++corner) {
        glm::dvec3 floor;
        // The neighbourhood within the image (a fill takes no neighbour outside it).
        const double px = (corner & 1) ? std::min<double>(x + 1 + reach, kSize) : std::max<double>(double(x) - reach, 0.0);
        const double py = (corner >> 1) ? std::min<double>(y + 1 + reach, kSize) : std::max<double>(double(y) - reach, 0.0);
        glm::dvec3 d = ref::pinholeRay(c.pinhole(), kSize, kSize, px, py);
        if (!ref::refractedFloorPoint(c.reference, eye, d, 8, floor)) {
            r.onFloor = false;
            return r;
        }
        const double depth = glm::dot(floor - eye, forward);
        const glm::dvec2 motion = texelOf(before, floor) - texelOf(now.viewProj, floor);
        r.depthLo = std::min(r.depthLo, depth);
        r.depthHi = std::max(r.depthHi, depth);
        r.motionLo = glm::min(r.motionLo, motion);
        r.motionHi = glm::max(r.motionHi, motion);
    }
    return r;
}

// Half precision's step relative to a value (10 mantissa bits: 2^-10 at the bottom of a binade), and its
// absolute step at a magnitude v.
constexpr double kHalfStep = 1.0 / 1024.0;
double halfStepAt(double v) { return std::ldexp(1.0, std::ilogb(std::max(v, 6.1e-5)) - 10); }

// Runs two frames (the camera moved by `step` between them) and checks every guided pixel of the last.
void expectGuidesOfTheFloorThroughThePane(rhi::IDevice& device, glm::vec3 step) {
    IndependentCase c = paneOverFloor();
    scene::Camera first = c.camera;
    first.eye -= step;
    first.target -= step;
    const scene::Camera cameras[] = {first, c.camera};
    CausticsSettings s = secondTypeSettings(128, 1.0f);
    s.seed = seedOffset() + 1;
    auto run = runCaustics(device, c.module, cameras, kSize, kSize, s);
    ASSERT_TRUE(run) << run.message();
    const CausticRun& g = run.value();
    ASSERT_EQ(g.guideObjectId.size(), size_t(kSize) * kSize);
    auto before = makeCameraConstants(first, kSize, kSize, 0);
    auto now = makeCameraConstants(c.camera, kSize, kSize, 1, &before.value().viewProj);
    ASSERT_TRUE(before && now);

    uint32_t guided = 0, outside = 0, wrongId = 0, ownPixel = 0;
    double worstNormal = 0.0, worstDepth = 0.0, worstMotion = 0.0;
    for (uint32_t y = 0; y < kSize; ++y)
        for (uint32_t x = 0; x < kSize; ++x) {
            const size_t i = size_t(y) * kSize + x;
            if (g.guideObjectId[i] == 0) continue;
            ++guided;
            if (g.guideObjectId[i] != kFloorId) ++wrongId;
            GuideRange r = expectedRange(c, x, y, now.value(), before.value().viewProj, 1);
            ASSERT_TRUE(r.onFloor) << "pixel (" << x << ", " << y << ") sees no floor through the pane";
            const glm::dvec4 dm(g.guideDepthMotion[i]);
            // Float32 on the GPU and its ray offsets at the pane's two faces: measured worst 4.2e-5 relative
            // depth (0.07 mm at 1.7 m) against the pixel's own range and 8.9e-5 px of motion (seed offset 0)
            // while the guides were float32; bounds 1e-4 and 1e-3 px, plus one step of half precision, the
            // guides' format since 2026-12-03 (a step, not half of one: Vulkan lets the store truncate, and
            // lavapipe does; measured worst 2.1e-4 relative depth with half).
            const double depthOff = std::max({r.depthLo - dm.x, dm.x - r.depthHi, 0.0}) / r.depthLo;
            const glm::dvec2 m(dm.y, dm.z);
            const double motionOff = std::max({r.motionLo.x - m.x, m.x - r.motionHi.x, r.motionLo.y - m.y, m.y - r.motionHi.y, 0.0});
            if (depthOff > 1e-4 + kHalfStep || motionOff > 1e-3 + halfStepAt(std::max(std::abs(m.x), std::abs(m.y)))) ++outside;
            GuideRange own = expectedRange(c, x, y, now.value(), before.value().viewProj, 0);
            const double ownTolerance = 1e-4 + kHalfStep;
            if (dm.x >= own.depthLo * (1.0 - ownTolerance) && dm.x <= own.depthHi * (1.0 + ownTolerance)) ++ownPixel;
            worstDepth = std::max(worstDepth, depthOff);
            worstMotion = std::max(worstMotion, motionOff);
            worstNormal = std::max(worstNormal, double(glm::length(glm::vec3(g.guideNormal[i]) - glm::vec3(0.0f, 1.0f, 0.0f))));
        }
    std::printf("[ measured ] %u of %u pixels guided, %u with their own pixel's depth; %u outside the 3x3 range (worst: "
                "depth %.2e relative, motion %.2e px), %u with another id, normal off by at most %.2e\n",
                guided, kSize * kSize, ownPixel, outside, worstDepth, worstMotion, wrongId, worstNormal);
    // A sample refracts at both faces with probability (1 - R)^2 = 0.92 (R = 0.04 at normal incidence);
    // a reflected one leaves towards the sky and makes no sphere (3,785 of 4,096 pixels had one, seed
    // offset 0). The fill gives such a pixel a neighbour's guides unless all 8 had none (0.08^8).
    EXPECT_EQ(guided, kSize * kSize);
    // The pixels whose own sample made the sphere hold their own receiver: 92 % (sd 0.4 %) and more, as a
    // filled pixel's neighbour may lie at nearly the same depth.
    EXPECT_GT(ownPixel, uint32_t(0.88 * kSize * kSize));
    EXPECT_EQ(wrongId, 0u);
    // Half precision: 2^-11 per component.
    EXPECT_LT(worstNormal, 2e-3);
    // Paths reflected twice inside the pane (probability R^2 (1 - R)^2 = 0.15 %) reach the floor 2 cm
    // further on; nothing else may leave the pixel's range.
    EXPECT_LE(outside, uint32_t(0.01 * guided));
}

TEST_F(SecondTypeGuides, StillCameraHoldsTheFloorSeenThroughThePane) {
    expectGuidesOfTheFloorThroughThePane(*device, glm::vec3(0.0f));
}

TEST_F(SecondTypeGuides, MovingCameraHoldsTheFloorPointsScreenMotion) {
    expectGuidesOfTheFloorThroughThePane(*device, glm::vec3(0.0f, 0.0f, 0.02f));
}

// The filter on a camera that slides 1 cm a frame (about 1.3 px on the floor) for 8 frames past the plate
// case (a glass ball's side caustic seen through a pane): the second type, filtered on its own guides
// and reprojected with the receiver's motion, keeps its peak where the reference puts it for the last
// camera (a history reprojected with the pane's depth would trail it by up to a frame's motion per
// frame) and its energy. Measured (offset 0): energy 0.9995, peak 0.07 px off; bounds: the 5 %
// energy and 0.5 px.
TEST_F(SecondTypeGuides, FilteredSecondTypeFollowsAMovingCamera) {
    IndependentCase c = plate();
    constexpr uint32_t kFrames = 8, kView = 96;
    std::vector<scene::Camera> cameras;
    for (uint32_t k = 0; k < kFrames; ++k) {
        scene::Camera cam = c.camera;
        const glm::vec3 step(0.0f, 0.0f, 0.01f * float(int(k) - int(kFrames) + 1));
        cam.eye += step;
        cam.target += step;
        cameras.push_back(cam);
    }
    CausticsSettings s = secondTypeSettings(512, 1.0f);
    s.filter = true;
    s.filterSecondTypeApart = true;
    s.seed = seedOffset() + 1;
    auto run = runCaustics(*device, c.module, cameras, kView, kView, s);
    ASSERT_TRUE(run) << run.message();

    ref::EstimateOptions o;
    o.width = o.height = kView;
    o.photons = 8'000'000;
    o.histogramResolution = 1024;
    o.receiverCentreX = c.receiverX;
    o.receiverHalfSize = c.receiverHalfSize;
    o.seed = seedOffset();
    ref::SecondTypeImage r = ref::renderSecondType(c.reference, c.pinhole(), ref::traceFloorPhotons(c.reference, o), o);
    std::vector<double> gl = luminances(run.value().secondType), rl = luminances(r.radiance);
    PeakAt pr = peak3x3At(rl, kView);
    double cx = pr.x, cy = pr.y, gx, gy, rx, ry;
    for (int k = 0; k < 2; ++k) featureCentroid(rl, kView, cx, cy, 4.0, cx, cy);
    featureCentroid(gl, kView, cx, cy, 4.0, gx, gy);
    featureCentroid(rl, kView, cx, cy, 4.0, rx, ry);
    const double energy = total(gl) / total(rl), shift = std::hypot(gx - rx, gy - ry);
    std::printf("[ measured ] filtered second type after %u moving frames: energy GPU/reference %.4f, peak %.2f px off\n",
                kFrames, energy, shift);
    EXPECT_NEAR(energy, 1.0, 0.05);
    EXPECT_LT(shift, 0.5);
}

// A still view keeps the second type's history where each frame's jittered camera path reaches another
// receiver (docs/caustics.md "Second-type guides", still views): through the water glass's curved walls
// and at its rim the receiver's depth, normal or object changes from frame to frame, and a history tested
// against them restarted every frame. With the temporal pass alone (no a-trous iteration) the filtered
// second type after kFrames still frames is the mean of those frames' unfiltered second type (the same
// random keys), up to half precision and the history test's rare drops (a fall restarts a pixel at this
// frame's value). Measured (lavapipe, 2026-12-05, CAUSTICS_SECOND_TYPE_SEED 0 / 1 / 2): relative L1 0.0086
// / 0.0079 / 0.0060 (0, 0 and 3 pixels zero where the mean exceeds 5 % of its peak); with the receiver
// tested in a still view (kTemporalStillView 0) 0.0270 (offset 0) and 0.0236 (offset 2), with 1 and 3 such
// zero pixels, which therefore say nothing and are only printed. Bound: L1 0.015, 1.7x the worst offset
// and 0.6x the rule off's best.
TEST_F(SecondTypeGuides, StillViewHistoryIsTheMeanOfItsJitteredFrames) {
    const IndependentCase c = waterGlass();
    constexpr uint32_t kFrames = 8, kView = 96;
    CausticsSettings s = secondTypeSettings(256, 1.0f);
    s.seed = seedOffset() + 1;
    std::vector<glm::dvec3> mean(size_t(kView) * kView, glm::dvec3(0.0));
    for (uint32_t frames = 1; frames <= kFrames; ++frames) {   // frame index frames - 1, unfiltered
        auto frame = runCaustics(*device, c.module, c.camera, kView, kView, s, frames);
        ASSERT_TRUE(frame) << frame.message();
        for (size_t i = 0; i < mean.size(); ++i) mean[i] += glm::dvec3(frame.value().secondType[i]) / double(kFrames);
    }
    s.filter = true;
    s.filterSecondTypeApart = true;
    s.atrousIterations = 0;
    auto filtered = runCaustics(*device, c.module, c.camera, kView, kView, s, kFrames);
    ASSERT_TRUE(filtered) << filtered.message();
    std::vector<glm::vec3> m(mean.size());
    for (size_t i = 0; i < mean.size(); ++i) m[i] = glm::vec3(mean[i]);
    const std::vector<double> fl = luminances(filtered.value().secondType), ml = luminances(m);
    const double peak = *std::max_element(ml.begin(), ml.end());
    ASSERT_GT(peak, 0.0) << "no second type in view";
    double l1 = 0.0, sum = 0.0;
    uint32_t zero = 0;
    for (size_t i = 0; i < ml.size(); ++i) {
        l1 += std::abs(fl[i] - ml[i]);
        sum += ml[i];
        if (ml[i] > 0.05 * peak && fl[i] == 0.0) ++zero;
    }
    std::printf("[ measured ] water glass, %u still frames, temporal pass only: relative L1 to the frames' mean %.4f, "
                "%u pixels zero where the mean exceeds 5 %% of its peak\n",
                kFrames, l1 / sum, zero);
    EXPECT_LT(l1 / sum, 0.015);
}

}  // namespace
}  // namespace caustics::test
