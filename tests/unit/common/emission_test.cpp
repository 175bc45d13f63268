#include <cmath>

#include <gtest/gtest.h>

#include "common/emission.h"

namespace sh = caustics::shader;

namespace {
double sumTexelSolidAngles(uint32_t n, float tanHalf) {
    double sum = 0;
    for (uint32_t y = 0; y < n; ++y)
        for (uint32_t x = 0; x < n; ++x) sum += sh::perspectiveTexelSolidAngle(sh::uint2(x, y), float(n), tanHalf);
    return sum;
}
}  // namespace

// Float rounding per texel is ~1e-7 relative (see emission.h); 1e-5 relative leaves a wide margin.
TEST(Emission, PerspectiveTexelSolidAnglesSumToFrustumSolidAngle) {
    for (float halfDeg : {10.0f, 30.0f, 45.0f, 70.0f}) {
        float t = std::tan(glm::radians(halfDeg));
        double expected = 4.0 * std::atan(double(t) * t / std::sqrt(1.0 + 2.0 * t * t));
        EXPECT_NEAR(sumTexelSolidAngles(512, t) / expected, 1.0, 1e-5) << halfDeg;
        EXPECT_NEAR(sh::perspectiveFrustumSolidAngle(t) / expected, 1.0, 1e-6);
    }
}

TEST(Emission, SixCubeFacesCoverTheWholeSphere) {
    EXPECT_NEAR(6.0 * sumTexelSolidAngles(128, 1.0f), 4.0 * M_PI, 4.0 * M_PI * 1e-5);
}

TEST(Emission, TexelSolidAngleMatchesAtanRectangleFormula) {
    // The atan-difference form is exact in double; compare one texel at the map's edge.
    uint32_t n = 64, x = 63, y = 5;
    double t = 1.0, x0 = t * (2.0 * x / n - 1), x1 = t * (2.0 * (x + 1) / n - 1);
    double y0 = t * (2.0 * y / n - 1), y1 = t * (2.0 * (y + 1) / n - 1);
    auto f = [](double a, double b) { return std::atan(a * b / std::sqrt(1 + a * a + b * b)); };
    double expected = f(x1, y1) - f(x0, y1) - f(x1, y0) + f(x0, y0);
    EXPECT_NEAR(sh::perspectiveTexelSolidAngle(sh::uint2(x, y), float(n), 1.0f) / expected, 1.0, 1e-5);
}

// Sum over the texels of a spot light's map of photonFluxPerspective (falloff at the texel centre)
// equals the analytic flux of the KHR_lights_punctual falloff. Midpoint-rule error at the cone's
// inner kink is O(1/N); 2e-3 relative for N = 512.
TEST(Emission, SpotMapFluxSumsToAnalyticSpotFlux) {
    const float intensity = 100.0f, inner = glm::radians(20.0f), outer = glm::radians(30.0f);
    const uint32_t n = 512;
    const float t = std::tan(outer);
    double sum = 0;
    for (uint32_t y = 0; y < n; ++y) {
        for (uint32_t x = 0; x < n; ++x) {
            glm::vec2 q = sh::perspectiveMapPlanePoint(glm::vec2(x + 0.5f, y + 0.5f), float(n), t);
            float cosTheta = 1.0f / std::sqrt(1.0f + glm::dot(q, q));
            float falloff = sh::spotAttenuation(cosTheta, std::cos(inner), std::cos(outer));
            sum += falloff * sh::photonFluxPerspective(intensity, sh::perspectiveTexelSolidAngle(sh::uint2(x, y), float(n), t), 1.0f);
        }
    }
    double expected = 2.0 * M_PI * intensity * ((1 - std::cos(inner)) + (std::cos(inner) - std::cos(outer)) / 3.0);
    EXPECT_NEAR(sh::spotLightFlux(intensity, std::cos(inner), std::cos(outer)) / expected, 1.0, 1e-6);
    EXPECT_NEAR(sum / expected, 1.0, 2e-3);
}

TEST(Emission, OrthographicMapFluxSumsToIlluminanceTimesArea) {
    const float illuminance = 7.0f, halfExtent = 1.5f;
    const uint32_t n = 300, rays = 4;
    double sum = 0;
    for (uint32_t i = 0; i < n * n * rays; ++i)
        sum += sh::photonFluxOrthographic(illuminance, sh::orthographicTexelArea(halfExtent, float(n)), float(rays));
    EXPECT_NEAR(sum / (illuminance * 4.0 * halfExtent * halfExtent), 1.0, 1e-5);
}

TEST(Emission, SpotAttenuationIsOneInsideZeroOutsideAndSmoothBetween) {
    float ci = std::cos(0.2f), co = std::cos(0.4f);
    EXPECT_EQ(sh::spotAttenuation(1.0f, ci, co), 1.0f);
    EXPECT_EQ(sh::spotAttenuation(std::cos(0.5f), ci, co), 0.0f);
    float mid = sh::spotAttenuation(0.5f * (ci + co), ci, co);
    EXPECT_NEAR(mid, 0.25f, 1e-5f);
}
