// The host's projection conventions (camera_view.h): a reversed-Z, infinite-far projection renders the
// same caustics as the standard one (every pass that uses depth follows the convention).
#include <gtest/gtest.h>

#include <cstdio>

#include "caustics/scene/gpu_scene.h"
#include "gpu_test.h"
#include "module_frames.h"
#include "spot_sphere_scene.h"

namespace caustics::test {
namespace {

constexpr uint32_t kSize = 64;

class HostProjection : public GpuTest {};

// Measured (lavapipe 2026-11-30, "[ measured ]" line): standard vs reversed-Z infinite relative L1
// 4.8e-9, 1.1e-8 and 6.5e-8 in three runs, i.e. float32 summation-order noise of the atomic splats (same seed, same rays: only the
// G-buffer's depth values differ). Bound 1e-6, about 8 float32 epsilons (1.19e-7), since the order of
// atomic adds varies between runs; a pass that misreads reversed depth (a depth test with the standard
// compare keeps the farthest surface and drops the sphere's occlusion) changes the image by 0.1 or more.
constexpr double kMeasuredL1 = 6.5e-8;
constexpr double kBound = 1e-6;
static_assert(kBound > 10 * kMeasuredL1);

TEST_F(HostProjection, ReversedZInfiniteFarGivesTheSameCausticsAsStandardDepth) {
    scene::Scene scene = spotSphereScene();
    auto gpuScene = scene::GpuScene::create(*device, scene);
    ASSERT_TRUE(gpuScene) << gpuScene.message();
    CausticsSettings s;
    s.mapResolution = 64;
    s.raysPerTexel = 4.0f;
    s.filter = false;
    s.maxStoredHits = 1u << 14;
    auto render = [&](const ProjectionOptions& o) -> Result<FrameImage> {
        CAUSTICS_TRY(auto module, CausticsModule::create(device, scene, gpuScene.value(), s));
        CAUSTICS_TRY(auto frames, runModuleFrames(*device, *module, 1, 1, [&](uint32_t) {
            ViewRequest v;
            v.inputs.camera = cameraViewMatrices(spotSphereCamera(), kSize, kSize, o);
            v.inputs.width = v.inputs.height = kSize;
            return std::vector<ViewRequest>{v};
        }));
        return frames[0][0];
    };
    auto standard = render(ProjectionOptions{});
    ASSERT_TRUE(standard) << standard.message();
    auto reversed = render(ProjectionOptions{.reversedZ = true, .infiniteFar = true});
    ASSERT_TRUE(reversed) << reversed.message();
    const double l1 = relativeL1(reversed.value(), standard.value());
    std::printf("[ measured ] reversed-Z infinite vs standard: relative L1 %.4g, energy %.4f / %.4f\n", l1,
                totalLuminance(reversed.value()), totalLuminance(standard.value()));
    EXPECT_GT(totalLuminance(standard.value()), 0.0);
    EXPECT_LT(l1, kBound);
}

}  // namespace
}  // namespace caustics::test
