// The caustic filter's a-trous body (passes/caustic_filter/shaders/atrous.h) compiled as C++: the
// spreading weight (docs/caustics.md "Filter", "Cost").
#include <gtest/gtest.h>

#include <cmath>

#include "caustic_filter/shaders/atrous.h"

namespace caustics::shader {
namespace {

// The weights: the B3 kernel's 25 taps sum to 1; on a plane (depth along the gradient), equal normals
// and equal luminance every weight is the kernel tap; a luminance difference of 3 deviations of the
// difference keeps exp(-4.5) of it, a normal 10 degrees off cos(10 deg)^128 (0.14).
TEST(AtrousBody, SpreadWeightIsTheKernelOnAPlaneAndStopsAtEdges) {
    float sum = 0.0f;
    const float2 grad(0.01f, -0.02f);
    const float3 n(0.0f, 0.0f, 1.0f);
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            const int2 offset = int2(dx, dy) * 2;
            const float zp = 5.0f + glm::dot(grad, float2(offset));
            const float w = atrousSpreadWeight(int2(dx, dy), 2, 5.0f, zp, grad, n, n, 1.0f, 1.0f, 0.1f, 0.1f, 1.0f, 0.0f);
            // zp's float rounding (half an ulp at 5, 2.4e-7) over the depth term's scale (>= 0.02): <= 1.2e-5.
            const float tap = atrousKernelTap(std::abs(dx)) * atrousKernelTap(std::abs(dy));
            EXPECT_NEAR(w, tap, 2e-5f * tap);
            sum += w;
        }
    EXPECT_NEAR(sum, 1.0f, 2e-5f);
    const float centre = atrousKernelTap(0) * atrousKernelTap(0);
    // Var_q + Var_p = 0.02, sigma 1: a difference of 3 sqrt(0.02) is 3 deviations.
    const float lum = atrousSpreadWeight(int2(0), 1, 5.0f, 5.0f, grad, n, n, 1.0f, 1.0f + 3.0f * std::sqrt(0.02f), 0.01f,
                                         0.01f, 1.0f, 0.0f);
    EXPECT_NEAR(lum / centre, std::exp(-4.5f), 1e-5f);
    const float c10 = std::cos(glm::radians(10.0f));
    const float3 tilted(std::sin(glm::radians(10.0f)), 0.0f, c10);
    EXPECT_NEAR(atrousSpreadWeight(int2(0), 1, 5.0f, 5.0f, grad, n, tilted, 1.0f, 1.0f, 0.01f, 0.01f, 1.0f, 0.0f) / centre,
                std::pow(c10, 128.0f), 1e-5f);
}

}  // namespace
}  // namespace caustics::shader
