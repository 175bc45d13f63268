// Frames and views (docs/embedding.md "Frames and views"): per-view filter history, per-frame state
// committed at execution, host-chosen frames in flight.
#include <gtest/gtest.h>

#include <cstdio>

#include "caustics/scene/gpu_scene.h"
#include "module/caustics_view.h"
#include "gpu_test.h"
#include "module_frames.h"
#include "spot_sphere_scene.h"

namespace caustics::test {
namespace {

constexpr uint32_t kSize = 48;

class Views : public GpuTest {};
class FramesInFlight : public GpuTest {};

CausticsSettings filteredSettings(uint32_t framesInFlight = 3) {
    CausticsSettings s;
    s.mapResolution = 64;
    s.raysPerTexel = 2.0f;
    s.secondType = false;
    s.filter = true;
    s.maxStoredHits = 1u << 12;
    s.framesInFlight = framesInFlight;
    return s;
}

scene::Camera sideCamera() {
    scene::Camera c = spotSphereCamera();
    c.eye = {1.8f, 1.2f, 1.4f};   // the same caustic from another side: a different history
    return c;
}

ViewRequest request(const scene::Camera& cam, CausticsView* view) { return viewOf(cam, kSize, ModuleOutput::Caustics, view); }

// Float atomics make two runs of the same frames differ slightly; this many frames give the filter a
// history worth sharing.
constexpr uint32_t kFrames = 4;

// Measured (lavapipe 2026-12-02, "[ measured ]" lines, four runs, with the half-precision tile-pool
// filter of docs/caustics.md "Filter"): the same view rendered twice alone differs by 0 or 1.26e-4, and
// the main view rendered next to the side view differs from it alone by the same two values: the order
// of atomic adds flips a few pixels' rounding to half precision (1/2048 relative), which the a-trous
// luminance weights spread; before the half-precision history the spread was 1.6e-6 to 6.1e-6. The
// side view's image differs from the main one by 0.369. Were the history shared, the main view's
// temporal pass (1/n average) would give (n - 1)/n = 75 % weight at frame 4 to the side view's history
// wherever its reprojection test passes, moving the result by a large fraction of 0.369. Bound 1e-3:
// 8x the largest measurement, still over 100x below what a shared history does.
constexpr double kViewBound = 1e-3;

TEST_F(Views, TwoViewsInOneFrameKeepIndependentHistories) {
    scene::Scene scene = spotSphereScene();
    auto gpuScene = scene::GpuScene::create(*device, scene);
    ASSERT_TRUE(gpuScene) << gpuScene.message();
    const scene::Camera main = spotSphereCamera(), side = sideCamera();

    auto alone = [&]() -> Result<FrameImage> {
        CAUSTICS_TRY(auto module, CausticsModule::create(device, scene, gpuScene.value(), filteredSettings()));
        CAUSTICS_TRY(auto frames, runModuleFrames(*device, *module, kFrames, 1, [&](uint32_t) {
            return std::vector<ViewRequest>{request(main, nullptr)};
        }));
        return frames.back()[0];
    };
    auto mainAlone = alone();
    ASSERT_TRUE(mainAlone) << mainAlone.message();
    auto mainAgain = alone();
    ASSERT_TRUE(mainAgain) << mainAgain.message();

    auto module = CausticsModule::create(device, scene, gpuScene.value(), filteredSettings());
    ASSERT_TRUE(module) << module.message();
    auto sideView = module.value()->createView();
    ASSERT_TRUE(sideView) << sideView.message();
    auto both = runModuleFrames(*device, *module.value(), kFrames, 1, [&](uint32_t) {
        return std::vector<ViewRequest>{request(main, nullptr), request(side, sideView.value().get())};
    });
    ASSERT_TRUE(both) << both.message();
    const FrameImage& mainWithSide = both.value().back()[0];
    const FrameImage& sideImage = both.value().back()[1];

    const double repeat = relativeL1(mainAgain.value(), mainAlone.value());
    const double withSide = relativeL1(mainWithSide, mainAlone.value());
    const double viewsApart = relativeL1(sideImage, mainAlone.value());
    std::printf("[ measured ] main alone vs again %.3g, main with side view vs alone %.3g, side vs main %.3g\n",
                repeat, withSide, viewsApart);
    EXPECT_GT(viewsApart, 0.3) << "the two views must see different images for the test to mean anything";
    EXPECT_LT(withSide, kViewBound);
}

// A graph built and dropped commits nothing: the view's history stays as the last executed frame left it.
TEST_F(Views, GraphBuiltButNotExecutedLeavesTheHistoryAlone) {
    scene::Scene scene = spotSphereScene();
    auto gpuScene = scene::GpuScene::create(*device, scene);
    ASSERT_TRUE(gpuScene) << gpuScene.message();
    auto module = CausticsModule::create(device, scene, gpuScene.value(), filteredSettings());
    ASSERT_TRUE(module) << module.message();
    auto view = module.value()->createView();
    ASSERT_TRUE(view) << view.message();
    rg::RenderGraph dropped;
    FrameInputs in = request(spotSphereCamera(), view.value().get()).inputs;
    ASSERT_TRUE(module.value()->addPasses(dropped, in));
    EXPECT_FALSE(view.value()->impl().history.valid) << "built, not executed: no history yet";
    EXPECT_FALSE(view.value()->impl().lastViewProj.has_value()) << "built, not executed: no previous matrix";
}

// A host that sizes a frame at a new image size by building a graph it drops, with a stale frame number
// (the sample's viewer did: frame 0 after frames 0..3), then renders the next frame at that size: the
// dropped build made the new history look written, and the next frame read it in UNDEFINED layout (12
// validation errors before the fix, which fail this fixture). The next frame must be what it is without
// the dropped build: measured identical (relative L1 0 on lavapipe; bound kViewBound, the float-atomic
// order's noise of the test above).
TEST_F(Views, DroppedSizingBuildWithAStaleFrameNumberLeavesTheResizedHistoryUnwritten) {
    constexpr uint32_t kResized = 40, kFramesBefore = 4, kFramesAll = 6;
    scene::Scene scene = spotSphereScene();
    auto gpuScene = scene::GpuScene::create(*device, scene);
    ASSERT_TRUE(gpuScene) << gpuScene.message();
    auto run = [&](bool sizingBuild) -> Result<FrameImage> {
        CAUSTICS_TRY(auto module, CausticsModule::create(device, scene, gpuScene.value(), filteredSettings()));
        CAUSTICS_TRY(auto frames, runModuleFrames(*device, *module, kFramesAll, 1, [&](uint32_t n) {
            const uint32_t size = n < kFramesBefore ? kSize : kResized;
            if (sizingBuild && n == kFramesBefore) {
                rg::RenderGraph dropped;
                FrameInputs stale = viewOf(spotSphereCamera(), kResized).inputs;
                stale.frameIndex = 0;
                EXPECT_TRUE(module->addPasses(dropped, stale));
            }
            return std::vector<ViewRequest>{viewOf(spotSphereCamera(), size)};
        }));
        return frames.back()[0];
    };
    auto plain = run(false);
    ASSERT_TRUE(plain) << plain.message();
    auto sized = run(true);
    ASSERT_TRUE(sized) << sized.message();
    const double difference = relativeL1(sized.value(), plain.value());
    std::printf("[ measured ] last frame after a dropped sizing build vs without: %.3g\n", difference);
    EXPECT_EQ(sized.value().width, kResized);
    EXPECT_LT(difference, kViewBound);
}

// Measured (lavapipe 2026-11-30): 5 in flight vs 1 in flight over 8 frames of a moving scene, worst
// frame 1.7e-8 to 1.4e-7 over three runs (float-atomic summation order); first vs last frame of the run
// 1.21. On the H200 (2026-12-02, the caster-motion filter on: the moving sphere's history is kept and
// tested against each frame's photons) the first run in a process measured 1.65e-6 and three repeats 0
// (docs/measurements/h200/gpu_tests_session7.txt): the summation order's noise, passed through the
// history test's threshold. Bound 1e-5, 6x the largest measurement; a frame reading another frame's
// tables, camera or history differs by a large fraction of the frame-to-frame change (1.2-2.0).
constexpr double kInFlightBound = 1e-5;

TEST_F(FramesInFlight, FiveInFlightGiveTheSameImagesAsOne) {
    constexpr uint32_t kLiveFrames = 8;
    auto run = [&](uint32_t inFlight) -> Result<std::vector<std::vector<FrameImage>>> {
        scene::Scene scene = spotSphereScene();
        const glm::mat4 rest = scene.instances[sphereInstance(scene)].transform;
        CAUSTICS_TRY(scene::GpuScene gpuScene, scene::GpuScene::create(*device, scene));
        CAUSTICS_TRY(auto module, CausticsModule::create(device, scene, gpuScene, filteredSettings(inFlight)));
        return runModuleFrames(*device, *module, kLiveFrames, inFlight, [&](uint32_t n) {
            poseSpotSphere(scene, float(n) / float(kLiveFrames - 1), rest);
            return std::vector<ViewRequest>{request(spotSphereCamera(), nullptr)};
        });
    };
    auto one = run(1);
    ASSERT_TRUE(one) << one.message();
    auto five = run(5);
    ASSERT_TRUE(five) << five.message();
    double worst = 0.0;
    for (uint32_t n = 0; n < kLiveFrames; ++n) worst = std::max(worst, relativeL1(five.value()[n][0], one.value()[n][0]));
    const double step = relativeL1(one.value()[kLiveFrames - 1][0], one.value()[0][0]);
    std::printf("[ measured ] 5 vs 1 in flight: worst frame %.3g; first vs last frame %.3g\n", worst, step);
    EXPECT_GT(step, 0.1) << "the scene must change over the run for the test to mean anything";
    EXPECT_LT(worst, kInFlightBound);
}

}  // namespace
}  // namespace caustics::test
