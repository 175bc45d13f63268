// The glTF metallic-roughness BRDF shared by direct lighting, the caustic splat and gather and the CPU
// reference (shaders/common/bsdf.h; docs/physics.md "One BSDF").
#include <cmath>

#include <gtest/gtest.h>

#include "common/bsdf.h"

namespace sh = caustics::shader;

namespace {
constexpr float kPi = 3.14159265358979f;

glm::vec3 direction(float thetaDeg, float phiDeg) {
    float t = glm::radians(thetaDeg), p = glm::radians(phiDeg);
    return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

// Hemispherical-directional reflectance rho(wo) = integral f(wi, wo) cos(wi) dwi by the midpoint rule
// in (cos theta, phi) (uniform in projected-solid-angle measure would hide the cosine).
float albedo(const sh::BrdfMaterial& m, const glm::vec3& wo) {
    const int nt = 512, np = 256;
    double sum = 0.0;
    for (int i = 0; i < nt; ++i) {
        float cosT = (float(i) + 0.5f) / nt;
        float sinT = std::sqrt(1.0f - cosT * cosT);
        for (int j = 0; j < np; ++j) {
            float phi = 2.0f * kPi * (float(j) + 0.5f) / np;
            glm::vec3 wi(sinT * std::cos(phi), sinT * std::sin(phi), cosT);
            sum += sh::evalGltfBrdf(m, glm::vec3(0, 0, 1), wi, wo).x * cosT;
        }
    }
    return float(sum * (1.0 / nt) * (2.0 * kPi / np));
}
}  // namespace

TEST(Bsdf, NormalIncidenceEqualsTheGltfFormulaWrittenOut) {
    // wi = wo = n: h = n, F = F0, D = 1 / (pi alpha^2), G = 1, so
    // f = (1 - F0) c / pi + F0 / (4 pi alpha^2) (glTF 2.0 Appendix B with the separable Smith G).
    const glm::vec3 n(0, 0, 1);
    for (float roughness : {0.3f, 0.6f, 1.0f}) {
        float alpha = roughness * roughness;
        glm::vec3 f = sh::receiverBrdf(glm::vec3(0.8f, 0.5f, 0.2f), 0.0f, roughness, n, n, n);
        glm::vec3 expected = 0.96f * glm::vec3(0.8f, 0.5f, 0.2f) / kPi + glm::vec3(0.04f / (4.0f * kPi * alpha * alpha));
        // 1e-5 relative: float rounding of D = a2 / (pi k^2) at small alpha (measured 6e-6 at roughness 0.3).
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[c], expected[c], 1e-5f * expected[c]) << roughness;
    }
}

TEST(Bsdf, ZeroF0IsExactlyLambertAtEveryAngle) {
    sh::BrdfMaterial m = sh::lambertOnlyBrdfMaterial(glm::vec3(0.7f, 0.4f, 0.1f));
    for (float ti : {0.0f, 30.0f, 60.0f, 85.0f})
        for (float to : {0.0f, 45.0f, 80.0f}) {
            glm::vec3 f = sh::evalGltfBrdf(m, glm::vec3(0, 0, 1), direction(ti, 0.0f), direction(to, 140.0f));
            EXPECT_FLOAT_EQ(f.x, 0.7f / kPi);
            EXPECT_FLOAT_EQ(f.z, 0.1f / kPi);
        }
}

TEST(Bsdf, ReciprocalInIncomingAndOutgoing) {
    for (float metallic : {0.0f, 1.0f})
        for (float ti : {10.0f, 50.0f, 75.0f})
            for (float to : {5.0f, 40.0f, 70.0f}) {
                glm::vec3 a = direction(ti, 20.0f), b = direction(to, 230.0f);
                glm::vec3 n(0, 0, 1), c(0.9f, 0.6f, 0.3f);
                glm::vec3 fab = sh::receiverBrdf(c, metallic, 0.5f, n, a, b);
                glm::vec3 fba = sh::receiverBrdf(c, metallic, 0.5f, n, b, a);
                for (int k = 0; k < 3; ++k) EXPECT_NEAR(fab[k], fba[k], 1e-5f * fab[k]);
            }
}

TEST(Bsdf, BelowTheSurfaceReflectsNothing) {
    glm::vec3 n(0, 0, 1), up = direction(30, 0), down = -direction(30, 90);
    EXPECT_EQ(sh::receiverBrdf(glm::vec3(1), 0.0f, 1.0f, n, up, down), glm::vec3(0));
    EXPECT_EQ(sh::receiverBrdf(glm::vec3(1), 0.0f, 1.0f, n, down, up), glm::vec3(0));
}

TEST(Bsdf, WhiteRoughDielectricConservesEnergy) {
    // Measured: rho = 0.972 at normal view, 0.974 at 60 deg (the (1 - F) diffuse weight and the
    // single-scattering GGX lobe both lose a little); energy is never created.
    sh::BrdfMaterial m = sh::makeBrdfMaterial(glm::vec3(1.0f), 0.0f, 1.0f, 0.0f, sh::kGltfDielectricF0);
    for (float to : {0.0f, 60.0f}) {
        float rho = albedo(m, direction(to, 0.0f));
        EXPECT_LE(rho, 1.0f) << to;
        EXPECT_GT(rho, 0.9f) << to;
    }
}

TEST(Bsdf, MetalHasNoDiffuseLayer) {
    // Far from the mirror direction a smooth-ish metal keeps only the GGX tail (measured 0.0029 at
    // roughness 0.2); a Lambert layer would add 0.9 / pi = 0.29.
    glm::vec3 n(0, 0, 1);
    glm::vec3 f = sh::receiverBrdf(glm::vec3(0.9f), 1.0f, 0.2f, n, direction(40, 0), direction(40, 90));
    EXPECT_LT(f.x, 0.01f);
    glm::vec3 mirror = sh::receiverBrdf(glm::vec3(0.9f), 1.0f, 0.2f, n, direction(40, 0), direction(40, 180));
    EXPECT_GT(mirror.x, 1.0f);
}

TEST(Bsdf, TransmissionRemovesTheDiffuseBase) {
    glm::vec3 n(0, 0, 1);
    auto opaque = sh::makeBrdfMaterial(glm::vec3(0.5f), 0.0f, 1.0f, 0.0f, 0.04f);
    auto clear = sh::makeBrdfMaterial(glm::vec3(0.5f), 0.0f, 1.0f, 1.0f, 0.04f);
    glm::vec3 a = direction(20, 0), b = direction(30, 120);
    glm::vec3 spec = sh::evalGltfBrdf(clear, n, a, b);
    glm::vec3 all = sh::evalGltfBrdf(opaque, n, a, b);
    EXPECT_GT(spec.x, 0.0f);                  // the GGX layer stays
    EXPECT_GT(all.x, spec.x + 0.9f * 0.5f * 0.9f / kPi);  // the diffuse base (1 - F) c / pi is gone
}
