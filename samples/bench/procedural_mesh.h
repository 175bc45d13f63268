#pragma once
// Benchmark geometry made by code (no assets on GPU machines): a displaced cube-sphere of a requested
// triangle count, with its triangles sorted in Morton order of their centroids.
#include <array>
#include <cstdint>
#include <vector>

namespace caustics::bench {

struct BenchMesh {
    std::vector<float> positions;    // xyz
    std::vector<uint32_t> indices;   // three per triangle
    std::array<float, 3> boundsMin{}, boundsMax{};
    uint32_t triangleCount() const { return uint32_t(indices.size() / 3); }
};

// 6 faces of n x n quads (12 n^2 triangles, n chosen to come closest to `targetTriangles`), each
// vertex pushed to radius 1 + a sum of sines so the surface is bumpy at several scales.
BenchMesh makeDisplacedSphere(uint32_t targetTriangles);

// Reorders triangles by the Morton code (Morton 1966; 10 bits per axis) of their centroids within the
// mesh bounds. lavapipe's BLAS builder splits the index range in order, so an unsorted mesh traces
// 10-17x slower there.
void sortTrianglesMorton(BenchMesh& mesh);

}  // namespace caustics::bench
