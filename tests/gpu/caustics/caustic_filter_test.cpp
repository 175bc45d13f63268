// The filter of paper 3.4 (temporal reprojection + edge-aware a-trous): runs clean under validation
// over several frames and keeps the caustic's mean radiance (the kernels are normalised).
#include <gtest/gtest.h>

#include <cmath>

#include "caustic_harness.h"
#include "caustic_test_scene.h"
#include "gpu_test.h"

namespace caustics::test {
namespace {

class CausticFilter : public GpuTest {};
constexpr uint32_t kFrames = 3;

TEST_F(CausticFilter, FilteredRadianceKeepsTheMeanOfTheUnfilteredCaustics) {
    CausticsSettings s = smallSettings();
    s.filter = true;
    s.raysPerTexel = 4.0f;
    auto run = runCaustics(*device, smallGlassSphereScene(), obliqueCamera(), 64, 64, s, kFrames);
    ASSERT_TRUE(run) << run.message();
    const CausticRun& r = run.value();
    double filtered = 0.0, raw = 0.0;
    for (size_t i = 0; i < r.radiance.size(); ++i) {
        ASSERT_TRUE(std::isfinite(r.radiance[i].x) && std::isfinite(r.radiance[i].y) && std::isfinite(r.radiance[i].z));
        filtered += r.radiance[i].y;
        raw += r.firstType[i].y + r.secondType[i].y;
    }
    ASSERT_GT(raw, 0.0);
    // Both are estimates of the same static image (the temporal history mixes earlier frames with
    // other seeds); 15 % covers the frame-to-frame noise of a 64x64 map and the a-trous kernel's
    // renormalisation at object borders.
    EXPECT_NEAR(filtered / raw, 1.0, 0.15);
}

}  // namespace
}  // namespace caustics::test
