#include <cmath>

#include <gtest/gtest.h>

#include "common/fresnel.h"

namespace sh = caustics::shader;

namespace {
// Power transmittances from the amplitude transmission coefficients (Born & Wolf 1.5.2), computed
// independently of the reflectance code: T = (nt cos t)/(ni cos i) * t^2.
float transmittanceUnpolarized(float cosI, float eta) {
    float sinT2 = (1 - cosI * cosI) / (eta * eta);
    float cosT = std::sqrt(1 - sinT2);
    float ts = 2 * cosI / (cosI + eta * cosT);
    float tp = 2 * cosI / (eta * cosI + cosT);
    float k = eta * cosT / cosI;
    return 0.5f * k * (ts * ts + tp * tp);
}
}  // namespace

TEST(Fresnel, NormalIncidenceEqualsSquaredIndexContrast) {
    for (float n : {1.33f, 1.5f, 2.42f}) {
        float expected = std::pow((n - 1) / (n + 1), 2.0f);
        EXPECT_NEAR(sh::fresnelDielectric(1.0f, n), expected, 1e-6f) << "n=" << n;
        EXPECT_NEAR(sh::fresnelDielectric(1.0f, 1.0f / n), expected, 1e-6f) << "leaving n=" << n;
        EXPECT_NEAR(sh::dielectricF0(n), expected, 1e-7f);
    }
}

TEST(Fresnel, PParallelReflectanceVanishesAtBrewsterAngle) {
    const float n = 1.5f;
    float cosB = std::cos(std::atan(n));
    glm::vec2 r = sh::fresnelDielectricPolarized(cosB, n);
    EXPECT_NEAR(r.y, 0.0f, 1e-7f);  // float rounding of cos(atan(n)) only
    EXPECT_GT(r.x, 0.1f);           // s-polarised light still reflects (0.148 for n = 1.5)
}

TEST(Fresnel, TotalInternalReflectionBeyondCriticalAngle) {
    const float eta = 1.0f / 1.5f;  // glass -> air
    float critical = std::asin(eta);
    EXPECT_EQ(sh::fresnelDielectric(std::cos(critical + 0.01f), eta), 1.0f);
    EXPECT_EQ(sh::fresnelDielectric(std::cos(1.5f), eta), 1.0f);
    EXPECT_LT(sh::fresnelDielectric(std::cos(critical - 0.01f), eta), 1.0f);
    glm::vec3 t;
    glm::vec3 d(std::sin(critical + 0.01f), 0.0f, -std::cos(critical + 0.01f));
    EXPECT_FALSE(sh::refractDirection(d, glm::vec3(0, 0, 1), 1.5f, t));
}

TEST(Fresnel, ReflectancePlusIndependentTransmittanceIsOne) {
    for (float eta : {1.5f, 1.0f / 1.5f, 2.0f}) {
        for (float deg = 0.0f; deg < 89.0f; deg += 3.0f) {
            float cosI = std::cos(glm::radians(deg));
            if ((1 - cosI * cosI) / (eta * eta) >= 1.0f) continue;  // TIR, covered above
            // 1e-5: float rounding of the two closed forms.
            EXPECT_NEAR(sh::fresnelDielectric(cosI, eta) + transmittanceUnpolarized(cosI, eta), 1.0f, 1e-5f)
                << "eta=" << eta << " theta=" << deg;
        }
    }
}

TEST(Fresnel, RefractionObeysSnellsLaw) {
    const glm::vec3 n(0, 0, 1);
    for (float deg = 0.0f; deg < 89.0f; deg += 7.0f) {
        float th = glm::radians(deg);
        glm::vec3 d = glm::normalize(glm::vec3(std::sin(th), 0.3f * std::sin(th), -std::cos(th)));
        glm::vec3 t;
        ASSERT_TRUE(sh::refractDirection(d, n, 1.0f / 1.5f, t));
        float sinI = glm::length(glm::cross(d, n));
        float sinT = glm::length(glm::cross(t, n));
        EXPECT_NEAR(1.0f * sinI, 1.5f * sinT, 1e-5f);
        EXPECT_NEAR(glm::length(t), 1.0f, 1e-5f);
        EXPECT_LT(t.z, 0.0f);                                      // continues into the medium
        EXPECT_NEAR(glm::dot(glm::cross(d, n), t), 0.0f, 1e-5f);   // stays in the plane of incidence
    }
}

TEST(Fresnel, SchlickMatchesF0AtNormalAndOneAtGrazing) {
    glm::vec3 f0(0.9f, 0.6f, 0.3f);
    glm::vec3 a = sh::fresnelSchlick(f0, 1.0f), b = sh::fresnelSchlick(f0, 0.0f);
    for (int c = 0; c < 3; ++c) {
        EXPECT_FLOAT_EQ(a[c], f0[c]);
        EXPECT_FLOAT_EQ(b[c], 1.0f);
    }
}
