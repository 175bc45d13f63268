// The second type in list order (common/specular_list.h; docs/caustics.md "Second-type memory"): with the
// filter running the second type apart and no AOV that shows a type alone, its buffer, image and guides
// hold one texel per listed specular pixel instead of one per screen pixel. That is a memory layout, not
// a change of the estimate: a frame in list order must give what the same frame gives in the screen
// layout (the types' own textures, as for an AOV), pixel for pixel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "caustic_harness.h"
#include "gpu_test.h"
#include "independent_cases.h"
#include "second_type_metrics.h"

namespace caustics::test {
namespace {

class SecondTypeListOrder : public GpuTest {};

struct LayoutDifference {
    double relativeL1 = 0.0;   // sum |a - b| / sum |a|
    double largest = 0.0;      // max |a - b| over the pixels and channels
    double energy = 0.0;       // sum |a|
};

LayoutDifference difference(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
    LayoutDifference d;
    double l1 = 0.0;
    for (size_t i = 0; i < a.size() && i < b.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            l1 += std::abs(double(a[i][c]) - double(b[i][c]));
            d.energy += std::abs(double(a[i][c]));
            d.largest = std::max(d.largest, std::abs(double(a[i][c]) - double(b[i][c])));
        }
    d.relativeL1 = d.energy > 0.0 ? l1 / d.energy : 0.0;
    return d;
}

// The ball from above (independent_cases.h), 4 filtered frames at 64 x 64: the camera sees the ball's
// caustic through the ball, so the second type runs on every frame and the filter keeps its history.
// The two layouts run the same arithmetic on the same values; float atomics may add in another order,
// which moves a value by a few ulps (lavapipe, 2026-12-04: identical images). Bound: 1e-4 of the
// caustic's energy in L1 and 1e-3 of its peak in any pixel, far below the seed-to-seed noise (the
// filtered ball's 3x3 peak moves by 5 % between seeds, second_type_independent_test.cpp).
TEST_F(SecondTypeListOrder, FilteredFramesMatchTheScreenLayout) {
    const IndependentCase c = ballFromAbove();
    constexpr uint32_t kSize = 64, kFrames = 4;
    CausticsSettings s = secondTypeSettings(256, 1.0f);
    s.filter = true;
    s.filterSecondTypeApart = true;
    auto screen = runCaustics(*device, c.module, c.camera, kSize, kSize, s, kFrames, true);
    ASSERT_TRUE(screen) << screen.message();
    auto list = runCaustics(*device, c.module, c.camera, kSize, kSize, s, kFrames, false);
    ASSERT_TRUE(list) << list.message();
    ASSERT_TRUE(list->secondTypeListOrder && !screen->secondTypeListOrder) << "one run in each layout";
    ASSERT_TRUE(list->firstType.empty()) << "no AOV: the harness ran the host's layout";

    const LayoutDifference radiance = difference(screen->radiance, list->radiance);
    const LayoutDifference second = difference(screen->secondType, list->secondType);
    double peak = 0.0;
    for (const glm::vec3& v : screen->radiance) peak = std::max(peak, double(std::max(v.r, std::max(v.g, v.b))));
    std::printf("[ measured ] list order against the screen layout: radiance L1 %.3g, largest %.3g (peak %.4g); "
                "second type L1 %.3g, largest %.3g\n",
                radiance.relativeL1, radiance.largest, peak, second.relativeL1, second.largest);
    ASSERT_GT(second.energy, 0.0) << "the second type must reach the image for the comparison to mean anything";
    EXPECT_LE(radiance.relativeL1, 1e-4);
    EXPECT_LE(radiance.largest, 1e-3 * peak);
    EXPECT_LE(second.relativeL1, 1e-4);

    // The guides too: the same receiver ids at the same pixels, depths within half precision's rounding.
    ASSERT_EQ(screen->guideObjectId.size(), list->guideObjectId.size());
    size_t guided = 0, idMismatches = 0;
    double depthError = 0.0;
    for (size_t i = 0; i < screen->guideObjectId.size(); ++i) {
        if (screen->guideObjectId[i] == 0u) continue;
        ++guided;
        if (list->guideObjectId[i] != screen->guideObjectId[i]) ++idMismatches;
        depthError = std::max(depthError, double(std::abs(list->guideDepthMotion[i].x - screen->guideDepthMotion[i].x)) /
                                              std::max(double(screen->guideDepthMotion[i].x), 1e-6));
    }
    std::printf("[ measured ] guided pixels %zu, id mismatches %zu, largest relative depth difference %.3g\n", guided,
                idMismatches, depthError);
    EXPECT_GT(guided, 100u);
    EXPECT_EQ(idMismatches, 0u);
    EXPECT_LE(depthError, 1e-3);
}

}  // namespace
}  // namespace caustics::test
