#include <algorithm>
#include <array>
#include <random>

#include <gtest/gtest.h>

#include "caustics/scene/mesh_builder.h"
#include "caustics/scene/mesh_utils.h"

namespace caustics::scene {
namespace {

std::vector<std::array<uint32_t, 3>> triangleSet(const Mesh& m) {
    std::vector<std::array<uint32_t, 3>> tris;
    for (size_t t = 0; t < m.indices.size(); t += 3) tris.push_back({m.indices[t], m.indices[t + 1], m.indices[t + 2]});
    std::sort(tris.begin(), tris.end());
    return tris;
}

// Mean distance between the centroids of consecutive triangles: what an in-order BLAS split feels.
double meanStep(const Mesh& m) {
    auto centroid = [&](size_t t) {
        return (m.positions[m.indices[3 * t]] + m.positions[m.indices[3 * t + 1]] + m.positions[m.indices[3 * t + 2]]) / 3.0f;
    };
    double sum = 0.0;
    size_t n = m.indices.size() / 3;
    for (size_t t = 1; t < n; ++t) sum += glm::length(centroid(t) - centroid(t - 1));
    return sum / double(n - 1);
}

Mesh shuffled(Mesh m) {
    std::vector<std::array<uint32_t, 3>> tris;
    for (size_t t = 0; t < m.indices.size(); t += 3) tris.push_back({m.indices[t], m.indices[t + 1], m.indices[t + 2]});
    std::mt19937 rng(42);
    std::shuffle(tris.begin(), tris.end(), rng);
    m.indices.clear();
    for (auto& t : tris) m.indices.insert(m.indices.end(), t.begin(), t.end());
    return m;
}

TEST(MortonSort, PreservesTheTriangleSetAndWinding) {
    Mesh m = shuffled(makeSphere(1.0f, 64, 32));
    auto before = triangleSet(m);
    sortTrianglesMorton(m);
    EXPECT_EQ(triangleSet(m), before);   // the same index triples: same triangles, same winding
}

TEST(MortonSort, MakesConsecutiveTrianglesSpatiallyClose) {
    Mesh m = shuffled(makePlane(10.0f, 10.0f, 64));
    double randomStep = meanStep(m);
    sortTrianglesMorton(m);
    // A Z-order curve over a 128x64-triangle grid steps about one cell (0.3 m) on average; random
    // order steps about half the plane (~10 m). A factor of 5 leaves a wide margin.
    EXPECT_LT(meanStep(m) * 5.0, randomStep);
}

TEST(MortonSort, CodeInterleavesAxesWithXMostSignificant) {
    EXPECT_EQ(mortonCode({0, 0, 0}), 0u);
    EXPECT_EQ(mortonCode({1, 1, 1}), (1u << 30) - 1);
    EXPECT_GT(mortonCode({0.6f, 0, 0}), mortonCode({0, 0.6f, 0}));
    EXPECT_GT(mortonCode({0, 0.6f, 0}), mortonCode({0, 0, 0.6f}));
}

TEST(MeshUtils, BoundsFollowTheInstanceTransform) {
    Scene s;
    s.materials.push_back({});
    s.meshes.push_back(makeBox({1, 1, 1}));
    Instance inst;
    inst.transform = glm::mat4(2.0f);
    inst.transform[3] = glm::vec4(10, 0, 0, 1);
    s.instances.push_back(inst);
    Aabb b = sceneBounds(s);
    EXPECT_FLOAT_EQ(b.min.x, 8.0f);
    EXPECT_FLOAT_EQ(b.max.x, 12.0f);
    EXPECT_EQ(triangleCount(s), 12u);
    EXPECT_TRUE(specularBounds(s).empty());   // the default material is diffuse
}

TEST(MeshUtils, SmoothNormalsOfASphereAreRadial) {
    Mesh m = makeSphere(1.0f, 32, 16);
    generateNormals(m, true);
    // Tolerance: area-weighted face normals of a 32x16 tessellation deviate from radial by < ~6 deg.
    for (size_t i = 0; i < m.positions.size(); ++i)
        if (std::abs(m.positions[i].y) < 0.99f) {
            EXPECT_GT(glm::dot(m.normals[i], glm::normalize(m.positions[i])), 0.99f);
        }
}

}  // namespace
}  // namespace caustics::scene
