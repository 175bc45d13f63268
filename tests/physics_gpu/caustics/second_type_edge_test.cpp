// Glass edges (docs/caustics.md "Glass edges"): a pixel whose centre sees a glass ball but whose
// footprint also covers the floor beside it shows both parts of its caustic light. Checked against the
// independent reference (tests/reference/second_type) reading first and second type together.
#include <gtest/gtest.h>

#include <cstdio>

#include "caustic_harness.h"
#include "gpu_test.h"
#include "independent_cases.h"
#include "independent_metrics.h"
#include "second_type_estimate.h"
#include "second_type_metrics.h"

namespace caustics::test {
namespace {

class GlassEdges : public GpuTest {};

constexpr uint32_t kSize = 96;

// A small glass ball 0.4 m over the floor, seen from straight above and below a wide glass plate that
// the sun shines through: the floor all round the ball carries caustic light (one refraction through the
// plate, first type where seen directly), so the ball's silhouette pixels have caustic light on both
// sides of the edge.
IndependentCase ballUnderAPlate() {
    IndependentCase c = emptyCase("ball under a plate");
    addBall(c, {0.0f, 0.4f, 0.0f}, 0.15f, 1.5f);
    addGlassBox(c, {0.0f, 1.5f, 0.0f}, {2.0f, 0.005f, 2.0f}, glm::mat3(1.0f), 1.5f);
    setDirectional(c, {0.0f, -1.0f, 0.0f}, 1.0f);
    c.camera = lookAt({0.0f, 1.2f, 0.0f}, {0.0f, 0.0f, 0.0f}, 40.0f, {0.0f, 0.0f, -1.0f});
    c.receiverHalfSize = 1.0;
    return c;
}

TEST_F(GlassEdges, SilhouettePixelsKeepTheFloorsCausticBesideTheGlass) {
    const IndependentCase c = ballUnderAPlate();
    CausticsSettings s = secondTypeSettings(512, 4.0f);
    auto gpu = averagedRun(*device, c.module, c.camera, kSize, s, 4);
    ASSERT_TRUE(gpu) << gpu.message();
    const CausticRun& g = gpu.value();

    ref::EstimateOptions o;
    o.width = o.height = kSize;
    o.photons = 8'000'000;
    o.histogramResolution = 512;
    o.receiverHalfSize = c.receiverHalfSize;
    o.countDirectPaths = true;
    o.seed = seedOffset();
    ref::SecondTypeImage r = ref::renderSecondType(c.reference, c.pinhole(), ref::traceFloorPhotons(c.reference, o), o);

    // Silhouette pixels: the G-buffer shows the ball at the centre, and a 4-neighbour shows the floor.
    const uint32_t ball = g.objectId[size_t(kSize / 2) * kSize + kSize / 2];
    double gpuSum = 0.0, refSum = 0.0, gpuInner = 0.0, refInner = 0.0;
    uint32_t edge = 0;
    for (uint32_t y = 1; y + 1 < kSize; ++y)
        for (uint32_t x = 1; x + 1 < kSize; ++x) {
            const size_t i = size_t(y) * kSize + x;
            if (g.objectId[i] != ball) continue;
            const bool onEdge = g.objectId[i - 1] != ball || g.objectId[i + 1] != ball || g.objectId[i - kSize] != ball ||
                                g.objectId[i + kSize] != ball;
            const double gv = luminance(g.firstType[i] + g.secondType[i]), rv = lum(r.radiance[i]);
            (onEdge ? gpuSum : gpuInner) += gv;
            (onEdge ? refSum : refInner) += rv;
            edge += onEdge ? 1 : 0;
        }
    std::printf("[ measured ] %u silhouette pixels: GPU/reference caustic %.4f (inside the silhouette %.4f)\n", edge,
                gpuSum / refSum, gpuInner / refInner);
    ASSERT_GT(edge, 100u);
    EXPECT_NEAR(gpuSum / refSum, 1.0, 0.05);
}

}  // namespace
}  // namespace caustics::test
