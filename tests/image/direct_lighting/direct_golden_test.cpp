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

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "gpu_test.h"
#include "module_harness.h"
#include "caustics/scene/builtin_scenes.h"

namespace caustics::test {
namespace {

namespace OIIO = OIIO_NAMESPACE;

constexpr uint32_t kSize = 256;
const std::string kGolden = std::string(CAUSTICS_SOURCE_DIR) + "/tests/image/golden/direct_builtin_256.exr";
const std::string kOutDir = CAUSTICS_BINARY_DIR;

bool writeRgb(const std::string& path, const std::vector<float>& rgb, OIIO::TypeDesc type) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) return false;
    OIIO::ImageSpec spec{int(kSize), int(kSize), 3, type};
    spec.attribute("compression", "zip");
    if (!out->open(path, spec)) return false;
    bool ok = out->write_image(OIIO::TypeDesc::FLOAT, rgb.data());
    out->close();
    return ok;
}

std::vector<float> readRgb(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in || in->spec().width != int(kSize) || in->spec().height != int(kSize)) return {};
    std::vector<float> rgb(size_t(kSize) * kSize * 3);
    if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, rgb.data())) return {};
    return rgb;
}

class DirectLightingGolden : public GpuTest {};

TEST_F(DirectLightingGolden, BuiltinSceneMatchesGoldenImage) {
    scene::Scene scene = scene::makeBuiltinScene("builtin");
    CausticsSettings settings;
    settings.causticsEnabled = false;
    settings.aov = CausticsAov::Direct;
    ASSERT_FALSE(scene.cameras.empty());
    auto frame = renderFrame(device, scene, settings, scene.cameras.front(), kSize, kSize);
    ASSERT_TRUE(frame.ok()) << frame.message();
    std::vector<float> rgb(size_t(kSize) * kSize * 3);
    for (size_t i = 0; i < size_t(kSize) * kSize; ++i)
        for (int c = 0; c < 3; ++c) rgb[3 * i + c] = frame->hdr[4 * i + c];

    const char* update = std::getenv("UPDATE_GOLDEN");
    if (update && std::string(update) == "1") {
        ASSERT_TRUE(writeRgb(kGolden, rgb, OIIO::TypeDesc::HALF)) << "cannot write " << kGolden;
        GTEST_SKIP() << "UPDATE_GOLDEN=1: wrote " << kGolden;
    }
    std::vector<float> golden = readRgb(kGolden);
    ASSERT_FALSE(golden.empty()) << "cannot read the golden " << kGolden
                                 << " (create it with UPDATE_GOLDEN=1, see the top of this file)";

    double sumSq = 0.0, sumGolden = 0.0;
    size_t off = 0;
    std::vector<float> diff(rgb.size());
    for (size_t i = 0; i < size_t(kSize) * kSize; ++i) {
        bool pixelOff = false;
        for (int c = 0; c < 3; ++c) {
            float a = rgb[3 * i + c], g = golden[3 * i + c];
            double d = double(a) - double(g);
            sumSq += d * d;
            sumGolden += std::abs(g);
            diff[3 * i + c] = float(std::abs(d));
            if (std::abs(d) > 0.02 * std::abs(g) + 0.002) pixelOff = true;
        }
        off += pixelOff ? 1 : 0;
    }
    size_t values = rgb.size();
    double meanGolden = sumGolden / double(values);
    double relRmse = std::sqrt(sumSq / double(values)) / std::max(meanGolden, 1e-12);
    double offFraction = double(off) / double(kSize * kSize);
    bool pass = relRmse <= 0.005 && offFraction <= 0.002;
    if (!pass) {
        writeRgb(kOutDir + "/direct_builtin_256.actual.exr", rgb, OIIO::TypeDesc::FLOAT);
        writeRgb(kOutDir + "/direct_builtin_256.diff.exr", diff, OIIO::TypeDesc::FLOAT);
    }
    EXPECT_LE(relRmse, 0.005) << "relative RMSE; actual and diff images in " << kOutDir;
    EXPECT_LE(offFraction, 0.002) << off << " pixels off; actual and diff images in " << kOutDir;
    EXPECT_GT(meanGolden, 0.0) << "the golden image is black";
}

}  // namespace
}  // namespace caustics::test
