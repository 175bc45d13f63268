// Golden-image test of the built-in scene's direct lighting (G-buffer + ray-traced shadows + the
// specular view chain; caustics off) at 256 x 256 on lavapipe.
//
// Metric, over linear RGB radiance (the RGBA32F `hdr` output with aov = Direct):
//  - relative RMSE  sqrt(mean((a - g)^2)) / mean(g)  <= 0.5 %
//  - fraction of pixels with a channel off by more than 2 % + 0.002 cd/m^2:  <= 0.2 %
// Why these: lavapipe is deterministic and nothing in the pass is random, so a correct build differs
// from the golden only by LLVM's float code generation (fused multiply-add, ordering) and the golden's
// half-float storage (relative step 2^-11 = 0.05 %); those stay far below both thresholds, while a
// broken shadow, a wrong light unit or a misplaced object moves whole regions well past them.
//
// Regenerate the golden (only after a deliberate change of the image, and look at it first):
//   UPDATE_GOLDEN=1 ctest --test-dir build -R DirectLightingGolden     (or scripts/update-goldens.sh)
// On failure the rendered image and a diff heat map are written next to the test binary.
#include <gtest/gtest.h>

#include <string>

#include "caustics/scene/builtin_scenes.h"
#include "golden_image.h"
#include "gpu_test.h"
#include "module_harness.h"

namespace caustics::test {
namespace {

constexpr uint32_t kSize = 256;
const std::string kGolden = std::string(CAUSTICS_SOURCE_DIR) + "/tests/image/golden/direct_builtin_256.exr";
const std::string kOutDir = CAUSTICS_BINARY_DIR;

class DirectLightingGolden : public GpuTest {};

TEST_F(DirectLightingGolden, BuiltinSceneMatchesGoldenImage) {
    scene::Scene scene = scene::makeBuiltinScene("builtin");
    CausticsSettings settings;
    settings.causticsEnabled = false;
    settings.aov = CausticsAov::Direct;
    ASSERT_FALSE(scene.cameras.empty());
    auto frame = renderFrame(device, scene, settings, scene.cameras.front(), kSize, kSize);
    ASSERT_TRUE(frame.ok()) << frame.message();
    RgbImage rgb = rgbFromRgba(frame->hdr, kSize, kSize);

    if (updateGoldenRequested()) {
        ASSERT_TRUE(writeExr(kGolden, rgb, true)) << "cannot write " << kGolden;
        GTEST_SKIP() << "UPDATE_GOLDEN=1: wrote " << kGolden;
    }
    auto golden = readExr(kGolden);
    ASSERT_TRUE(golden && golden->width == kSize && golden->height == kSize)
        << "cannot read the golden " << kGolden << " (create it with UPDATE_GOLDEN=1, see the top of this file)";

    ImageDiff d = compareImages(rgb, *golden, 0.02, 0.002);
    if (d.relativeRmse > 0.005 || d.offFraction > 0.002) {
        writeExr(kOutDir + "/direct_builtin_256.actual.exr", rgb, false);
        writeExr(kOutDir + "/direct_builtin_256.diff.exr", d.absoluteDifference, false);
    }
    EXPECT_LE(d.relativeRmse, 0.005) << "relative RMSE; actual and diff images in " << kOutDir;
    EXPECT_LE(d.offFraction, 0.002) << d.offFraction * kSize * kSize << " pixels off; actual and diff images in " << kOutDir;
    EXPECT_GT(d.energyRatio, 0.0) << "the rendered image is black";
}

}  // namespace
}  // namespace caustics::test
