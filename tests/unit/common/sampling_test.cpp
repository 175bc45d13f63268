#include <cmath>

#include <gtest/gtest.h>

#include "common/rng.h"
#include "common/sampling.h"
#include "common/volume.h"

namespace sh = caustics::shader;

TEST(OrthonormalBasis, IsOrthonormalAndRightHandedForAnyNormal) {
    sh::Rng rng = sh::rngCreate(1, 2, 3, 4);
    std::vector<glm::vec3> normals = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, 1, 0},
                                      glm::normalize(glm::vec3(1e-4f, 2e-4f, -1.0f))};
    for (int i = 0; i < 1000; ++i) normals.push_back(sh::sampleUniformSphere(sh::rngNextFloat2(rng)));
    for (const glm::vec3& n : normals) {
        sh::Onb o = sh::onbFromNormal(n);
        // 1e-5: float rounding near n.z = -1 (Duff et al. report ~1e-6 errors).
        EXPECT_NEAR(glm::length(o.t), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::length(o.b), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(o.t, o.b), 0.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(o.t, n), 0.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(o.b, n), 0.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(glm::cross(o.t, o.b), n), 1.0f, 1e-5f);
        glm::vec3 v(0.3f, -0.4f, 0.5f);
        glm::vec3 back = sh::onbToLocal(o, sh::onbToWorld(o, v));
        EXPECT_NEAR(glm::length(back - v), 0.0f, 1e-5f);
    }
}

// Moments of the sampled distributions; 200k samples give standard errors ~1e-3, tolerance 5e-3.
TEST(Sampling, CosineHemisphereHasMeanCosineTwoThirds) {
    sh::Rng rng = sh::rngCreate(7, 0, 0, 0);
    double sum = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        glm::vec3 w = sh::sampleCosineHemisphere(sh::rngNextFloat2(rng));
        ASSERT_GE(w.z, 0.0f);
        ASSERT_NEAR(glm::length(w), 1.0f, 1e-5f);
        sum += w.z;
    }
    EXPECT_NEAR(sum / n, 2.0 / 3.0, 5e-3);
}

TEST(Sampling, UniformSphereHasZeroMeanAndThirdSquaredZ) {
    sh::Rng rng = sh::rngCreate(8, 0, 0, 0);
    glm::dvec3 mean(0);
    double z2 = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        glm::vec3 w = sh::sampleUniformSphere(sh::rngNextFloat2(rng));
        mean += glm::dvec3(w);
        z2 += w.z * w.z;
    }
    EXPECT_LT(glm::length(mean / double(n)), 5e-3);
    EXPECT_NEAR(z2 / n, 1.0 / 3.0, 5e-3);
}

TEST(Sampling, UniformConeStaysInsideAndIsUniformInCosine) {
    sh::Rng rng = sh::rngCreate(9, 0, 0, 0);
    const float cosMax = 0.8f;
    double sum = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        glm::vec3 w = sh::sampleUniformCone(sh::rngNextFloat2(rng), cosMax);
        ASSERT_GE(w.z, cosMax - 1e-6f);
        sum += w.z;
    }
    EXPECT_NEAR(sum / n, 0.5 * (1.0 + cosMax), 1e-3);  // uniform solid angle = uniform cos theta
    EXPECT_NEAR(sh::uniformConePdf(cosMax), 1.0 / (2 * M_PI * 0.2), 1e-5);
}

TEST(Volume, BeerLambertKeepsAttenuationColorAfterAttenuationDistance) {
    glm::vec3 color(0.5f, 0.25f, 0.9f);
    glm::vec3 sigma = sh::volumeSigmaA(color, 2.0f);
    glm::vec3 t = sh::beerLambert(sigma, 2.0f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(t[c], color[c], 1e-6f);
    glm::vec3 t4 = sh::beerLambert(sigma, 4.0f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(t4[c], color[c] * color[c], 1e-6f);
    EXPECT_EQ(sh::volumeSigmaA(color, 0.0f), glm::vec3(0.0f));  // 0 = infinite distance
}
