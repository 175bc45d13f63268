// common/tone_map.h compiled as C++: the display transform the composite pass runs on the GPU.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "common/tone_map.h"

namespace {

using namespace caustics::shader;

TEST(ToneMap, ExtremeRadianceIsWhiteNotBlack) {
    // 1e38 squared overflows float: without the input clamp the fit was inf / inf = NaN, shown black.
    for (float radiance : {1e5f, 1e38f, std::numeric_limits<float>::max(), std::numeric_limits<float>::infinity()}) {
        float3 shown = acesFitted(splat3(radiance));
        EXPECT_FLOAT_EQ(shown.x, 1.0f) << radiance;
        EXPECT_FLOAT_EQ(shown.z, 1.0f) << radiance;
    }
}

TEST(ToneMap, OrdinaryRadianceFollowsTheNarkowiczFit) {
    for (float x : {0.0f, 0.05f, 0.5f, 1.0f, 4.0f, 50.0f}) {
        float expected = std::min(1.0f, (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f));
        EXPECT_NEAR(acesFitted(splat3(x)).y, expected, 1e-6f) << x;
    }
    EXPECT_FLOAT_EQ(acesFitted(splat3(-3.0f)).x, 0.0f);   // negative radiance (filter ringing) is black
}

}  // namespace
