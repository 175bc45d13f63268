// Specular instances share a caustic map layer only when they stand close together
// (caustics/specular_clusters.h): the table top's three objects share one, objects tens of metres
// apart get one each, so a ball's photon density does not depend on where the others stand.
#include <gtest/gtest.h>

#include "caustics/specular_clusters.h"

namespace caustics {
namespace {

TEST(SpecularClusters, EnclosingSphereHoldsBothSpheres) {
    const glm::vec4 a(0, 0, 0, 1), b(4, 0, 0, 0.5f);
    const glm::vec4 m = enclosingSphere(a, b);
    EXPECT_NEAR(m.w, 2.75f, 1e-5f);   // (4 + 1 + 0.5) / 2
    EXPECT_LE(glm::length(glm::vec3(m) - glm::vec3(a)) + a.w, m.w + 1e-5f);
    EXPECT_LE(glm::length(glm::vec3(m) - glm::vec3(b)) + b.w, m.w + 1e-5f);
    EXPECT_EQ(enclosingSphere(a, glm::vec4(0.2f, 0, 0, 0.1f)), a) << "b inside a";
}

TEST(SpecularClusters, TableTopObjectsShareOneLayer) {
    // The built-in table's glass, water, sphere and ring bounding spheres (metres).
    const std::vector<glm::vec4> s = {{-0.14f, 0.06f, 0.02f, 0.085f}, {-0.14f, 0.05f, 0.02f, 0.06f},
                                      {0.04f, 0.05f, 0.08f, 0.087f}, {0.2f, 0.015f, -0.05f, 0.073f}};
    auto clusters = clusterSpecularInstances(s, {0, 1, 2, 3});
    ASSERT_EQ(clusters.size(), 1u);
    EXPECT_EQ(clusters[0].instances, (std::vector<uint32_t>{0, 1, 2, 3}));
}

TEST(SpecularClusters, ObjectsFortyMetresApartGetALayerEach) {
    const std::vector<glm::vec4> s = {{0, 1, 0, 0.5f}, {40, 1, 0, 0.5f}, {41.5f, 0.2f, 0, 0.5f}};
    auto clusters = clusterSpecularInstances(s, {7, 9, 12});
    ASSERT_EQ(clusters.size(), 2u);
    EXPECT_EQ(clusters[0].instances, (std::vector<uint32_t>{7}));
    EXPECT_EQ(clusters[0].sphere, s[0]) << "the lone ball's layer is fitted to it alone";
    EXPECT_EQ(clusters[1].instances, (std::vector<uint32_t>{9, 12})) << "the two far objects 1.5 m apart share";
}

TEST(SpecularClusters, EveryMergedLayerKeepsItsWasteWithinTheRatio) {
    // A row of 20 balls 1.2 m apart (radius 0.5): each merge keeps merged r^2 <= 4 x member area.
    std::vector<glm::vec4> s;
    std::vector<uint32_t> ids;
    for (uint32_t i = 0; i < 20; ++i) {
        s.push_back({1.2f * float(i), 0, 0, 0.5f});
        ids.push_back(i);
    }
    auto clusters = clusterSpecularInstances(s, ids);
    size_t members = 0;
    for (const SpecularCluster& c : clusters) {
        EXPECT_LE(c.sphere.w * c.sphere.w, kClusterMergeAreaRatio * c.memberArea * 1.0001f);
        members += c.instances.size();
    }
    EXPECT_EQ(members, 20u) << "every instance in exactly one layer";
    EXPECT_GT(clusters.size(), 1u);
    EXPECT_LT(clusters.size(), 20u);
}

TEST(SpecularClusters, ManyInstancesArePooledOnAGridFirst) {
    // 4096 tiny spheres over a 100 m square: more than kMaxClusterSeeds; every instance still lands in one layer.
    std::vector<glm::vec4> s;
    std::vector<uint32_t> ids;
    for (uint32_t i = 0; i < 4096; ++i) {
        s.push_back({float(i % 64) * 1.6f, 0, float(i / 64) * 1.6f, 0.05f});
        ids.push_back(i);
    }
    auto clusters = clusterSpecularInstances(s, ids);
    size_t members = 0;
    for (const SpecularCluster& c : clusters) members += c.instances.size();
    EXPECT_EQ(members, 4096u);
    EXPECT_LE(clusters.size(), size_t(kMaxClusterSeeds));
}

}  // namespace
}  // namespace caustics
