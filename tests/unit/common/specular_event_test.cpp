#include <cmath>

#include <gtest/gtest.h>

#include "common/fresnel.h"
#include "common/rng.h"
#include "common/specular_event.h"

namespace sh = caustics::shader;

namespace {
sh::OpticalMaterial glass(float roughness = 0.0f) {
    sh::OpticalMaterial m;
    m.baseColor = glm::vec3(1.0f);
    m.metallic = 0.0f;
    m.roughness = roughness;
    m.transmission = 1.0f;
    m.ior = 1.5f;
    m.thinWalled = false;
    return m;
}
const glm::vec3 kUp(0, 0, 1);
}  // namespace

// 1e5 events: the refracted fraction has standard error sqrt(R(1-R)/n) ~ 6e-4; tolerance 3e-3 (5 sigma).
TEST(SpecularEvent, SmoothGlassRefractsWithProbabilityOneMinusFresnel) {
    sh::Rng rng = sh::rngCreate(1, 0, 0, 0);
    const float theta = glm::radians(50.0f);
    glm::vec3 d(std::sin(theta), 0.0f, -std::cos(theta));
    int refracted = 0;
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        sh::SpecularEvent ev = sh::sampleSpecularEvent(d, kUp, glass(), sh::rngNextFloat3(rng), sh::kTransportImportance);
        ASSERT_TRUE(ev.kind == sh::kEventReflect || ev.kind == sh::kEventRefract);
        EXPECT_FLOAT_EQ(ev.weight.x, 1.0f);  // Fresnel is in the probability, not in the weight
        if (ev.kind == sh::kEventRefract) {
            ++refracted;
            EXPECT_TRUE(ev.insideMedium);
            EXPECT_NEAR(std::sin(theta), 1.5f * std::sqrt(1 - ev.direction.z * ev.direction.z), 1e-5f);
        } else {
            EXPECT_NEAR(glm::length(ev.direction - glm::vec3(d.x, d.y, -d.z)), 0.0f, 1e-6f);
            EXPECT_FALSE(ev.insideMedium);
        }
    }
    float expected = 1.0f - sh::fresnelDielectric(std::cos(theta), 1.5f);
    EXPECT_NEAR(float(refracted) / n, expected, 3e-3f);
}

TEST(SpecularEvent, LeavingGlassBeyondCriticalAngleAlwaysReflectsInside) {
    sh::Rng rng = sh::rngCreate(2, 0, 0, 0);
    const float theta = glm::radians(45.0f);  // critical angle of n = 1.5 is 41.8 degrees
    glm::vec3 d(std::sin(theta), 0.0f, std::cos(theta));  // inside, travelling out through +z normal
    for (int i = 0; i < 1000; ++i) {
        sh::SpecularEvent ev = sh::sampleSpecularEvent(d, kUp, glass(), sh::rngNextFloat3(rng), sh::kTransportImportance);
        ASSERT_EQ(ev.kind, sh::kEventReflect);
        EXPECT_TRUE(ev.insideMedium);
        EXPECT_LT(ev.direction.z, 0.0f);
    }
}

TEST(SpecularEvent, RadianceTransportScalesRefractionByInverseSquaredIorRatio) {
    glm::vec3 d(0, 0, -1);
    glm::vec3 u(0.5f, 0.5f, 0.99f);  // pick > F: refract
    sh::SpecularEvent imp = sh::sampleSpecularEvent(d, kUp, glass(), u, sh::kTransportImportance);
    sh::SpecularEvent rad = sh::sampleSpecularEvent(d, kUp, glass(), u, sh::kTransportRadiance);
    ASSERT_EQ(imp.kind, sh::kEventRefract);
    EXPECT_FLOAT_EQ(imp.weight.x, 1.0f);             // flux is conserved across the interface
    EXPECT_NEAR(rad.weight.x, 1.0f / 2.25f, 1e-6f);  // (etaI / etaT)^2 entering n = 1.5
}

TEST(SpecularEvent, MetalReflectsMirrorWithSchlickWeight) {
    sh::OpticalMaterial m = glass();
    m.metallic = 1.0f;
    m.baseColor = glm::vec3(0.9f, 0.5f, 0.2f);
    glm::vec3 d = glm::normalize(glm::vec3(0.3f, 0.1f, -1.0f));
    sh::SpecularEvent ev = sh::sampleSpecularEvent(d, kUp, m, glm::vec3(0.2f, 0.7f, 0.5f), sh::kTransportImportance);
    ASSERT_EQ(ev.kind, sh::kEventReflect);
    EXPECT_NEAR(glm::length(ev.direction - glm::vec3(d.x, d.y, -d.z)), 0.0f, 1e-6f);
    glm::vec3 expected = sh::fresnelSchlick(m.baseColor, -d.z);
    EXPECT_NEAR(glm::length(ev.weight - expected), 0.0f, 1e-6f);
}

TEST(SpecularEvent, PartlyTransmissiveDielectricEndsInDiffuseBaseWithItsProbability) {
    sh::OpticalMaterial m = glass();
    m.transmission = 0.25f;
    sh::Rng rng = sh::rngCreate(3, 0, 0, 0);
    int diffuse = 0;
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        sh::SpecularEvent ev = sh::sampleSpecularEvent(glm::vec3(0, 0, -1), kUp, m, sh::rngNextFloat3(rng), sh::kTransportImportance);
        diffuse += ev.kind == sh::kEventDiffuse;
    }
    // (1 - F0)(1 - transmission) = 0.96 * 0.75; standard error 1.4e-3, tolerance 7e-3.
    EXPECT_NEAR(float(diffuse) / n, 0.96f * 0.75f, 7e-3f);
}

// A single-scattering microfacet BSDF with Smith shadowing may lose energy but never create it: the
// mean weight over many events is <= 1. 2e5 events, weights bounded by ~2: standard error < 3e-3.
TEST(SpecularEvent, RoughGlassDoesNotCreateEnergyAndKeepsMostOfIt) {
    for (float roughness : {0.1f, 0.3f}) {
        sh::Rng rng = sh::rngCreate(4, 0, 0, 0);
        glm::vec3 d = glm::normalize(glm::vec3(0.5f, 0.0f, -1.0f));
        double sum = 0;
        const int n = 200000;
        for (int i = 0; i < n; ++i) {
            sh::SpecularEvent ev = sh::sampleSpecularEvent(d, kUp, glass(roughness), sh::rngNextFloat3(rng), sh::kTransportImportance);
            if (ev.kind == sh::kEventRefract) {
                ASSERT_LT(ev.direction.z, 0.0f);
            } else if (ev.kind == sh::kEventReflect) {
                ASSERT_GT(ev.direction.z, 0.0f);
            }
            sum += ev.weight.x;
        }
        EXPECT_LT(sum / n, 1.0 + 1e-2) << roughness;
        EXPECT_GT(sum / n, 0.85) << roughness;  // GGX single-scatter loss at these roughnesses is a few %
    }
}

// The backward pass's lobe split picks lobes by u.z inside the intervals specularLobeInterval names: the
// centre of a lobe's interval must sample that lobe, and specularLobePickOutside must never land in it.
// A partly transmissive, partly metallic rough dielectric has all four lobes (chances 0.2 / ~0.03 / ~0.38 /
// ~0.38); u.z on a 1e-3 grid covers every interval.
TEST(SpecularEvent, LobeIntervalsPickTheirOwnLobeAndOutsidePicksAnother) {
    sh::OpticalMaterial m = glass(0.3f);
    m.metallic = 0.2f;
    m.transmission = 0.5f;
    const glm::vec3 d = glm::normalize(glm::vec3(0.3f, 0.0f, -1.0f));
    const glm::vec2 uv(0.37f, 0.61f);
    const sh::SpecularFacet facet = sh::specularFacet(d, kUp, m, uv);
    const sh::SpecularLobeChances c = sh::specularLobeChancesAt(facet, m);
    ASSERT_GT(c.metal, 0.0f);
    ASSERT_GT(c.reflect, 0.0f);
    ASSERT_GT(c.refract, 0.0f);
    ASSERT_GT(c.diffuse, 0.0f);
    EXPECT_NEAR(c.metal + c.reflect + c.refract + c.diffuse, 1.0f, 1e-6f);
    // Metal and dielectric reflection both reflect: tell them apart by the weight (Schlick vs 1).
    auto lobeOf = [&](float pick) {
        const sh::SpecularEvent ev = sh::sampleSpecularEventOnFacet(facet, d, m, pick, sh::kTransportRadiance);
        if (ev.kind == sh::kEventReflect) return pick < c.metal ? 0u : 1u;
        return ev.kind == sh::kEventRefract ? 2u : (ev.kind == sh::kEventDiffuse ? 3u : 99u);
    };
    for (uint32_t lobe = 0; lobe < 4; ++lobe) {
        EXPECT_EQ(lobeOf(sh::specularLobePickCentre(c, lobe)), lobe) << "centre of lobe " << lobe;
        const float chance = sh::specularLobeInterval(c, lobe).y;
        for (float u = 0.0f; u < 1.0f - chance; u += 1e-3f)
            EXPECT_NE(lobeOf(sh::specularLobePickOutside(c, lobe, u)), lobe) << "lobe " << lobe << ", u " << u;
    }
    EXPECT_EQ(sh::specularMostLikelyLobe(c), c.refract >= c.diffuse ? 2u : 3u);
}
