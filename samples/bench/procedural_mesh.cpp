#include "procedural_mesh.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace caustics::bench {
namespace {

float displacement(float x, float y, float z) {
    return 0.08f * std::sin(7.0f * x) * std::sin(9.0f * y) * std::sin(11.0f * z) +
           0.03f * std::sin(31.0f * x + 17.0f * y) + 0.01f * std::sin(97.0f * z + 53.0f * x);
}

// Spreads the low 10 bits of v to every third bit (the usual "part1by2" bit trick).
uint32_t spreadBits(uint32_t v) {
    v &= 0x3FF;
    v = (v | (v << 16)) & 0x030000FF;
    v = (v | (v << 8)) & 0x0300F00F;
    v = (v | (v << 4)) & 0x030C30C3;
    v = (v | (v << 2)) & 0x09249249;
    return v;
}

}  // namespace

BenchMesh makeDisplacedSphere(uint32_t targetTriangles) {
    const uint32_t n = std::max(1u, uint32_t(std::lround(std::sqrt(double(targetTriangles) / 12.0))));
    BenchMesh mesh;
    mesh.boundsMin = {1e30f, 1e30f, 1e30f};
    mesh.boundsMax = {-1e30f, -1e30f, -1e30f};
    // Face f: a fixed axis at +-1, the other two spanning [-1, 1].
    for (uint32_t face = 0; face < 6; ++face) {
        const uint32_t axis = face / 2;
        const float sign = face % 2 ? -1.0f : 1.0f;
        const uint32_t base = uint32_t(mesh.positions.size() / 3);
        for (uint32_t j = 0; j <= n; ++j) {
            for (uint32_t i = 0; i <= n; ++i) {
                float p[3];
                p[axis] = sign;
                p[(axis + 1) % 3] = -1.0f + 2.0f * float(i) / float(n);
                p[(axis + 2) % 3] = -1.0f + 2.0f * float(j) / float(n);
                const float len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
                const float x = p[0] / len, y = p[1] / len, z = p[2] / len;
                const float r = 1.0f + displacement(x, y, z);
                const float v[3] = {x * r, y * r, z * r};
                for (int k = 0; k < 3; ++k) {
                    mesh.positions.push_back(v[k]);
                    mesh.boundsMin[k] = std::min(mesh.boundsMin[k], v[k]);
                    mesh.boundsMax[k] = std::max(mesh.boundsMax[k], v[k]);
                }
            }
        }
        for (uint32_t j = 0; j < n; ++j) {
            for (uint32_t i = 0; i < n; ++i) {
                const uint32_t a = base + j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
                // Opposite faces mirror the parameterisation; flip their winding to keep normals outward.
                if (sign > 0) mesh.indices.insert(mesh.indices.end(), {a, b, d, a, d, c});
                else mesh.indices.insert(mesh.indices.end(), {a, d, b, a, c, d});
            }
        }
    }
    return mesh;
}

void sortTrianglesMorton(BenchMesh& mesh) {
    const uint32_t count = mesh.triangleCount();
    std::vector<uint32_t> codes(count);
    float scale[3];
    for (int k = 0; k < 3; ++k) scale[k] = 1023.0f / std::max(1e-20f, mesh.boundsMax[k] - mesh.boundsMin[k]);
    for (uint32_t t = 0; t < count; ++t) {
        uint32_t q[3];
        for (int k = 0; k < 3; ++k) {
            float c = 0;
            for (int v = 0; v < 3; ++v) c += mesh.positions[3 * mesh.indices[3 * t + v] + k];
            const float cell = (c / 3.0f - mesh.boundsMin[k]) * scale[k];
            q[k] = uint32_t(std::clamp(cell, 0.0f, 1023.0f));
        }
        codes[t] = (spreadBits(q[0]) << 2) | (spreadBits(q[1]) << 1) | spreadBits(q[2]);
    }
    std::vector<uint32_t> order(count);
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return codes[a] < codes[b]; });
    std::vector<uint32_t> sorted(mesh.indices.size());
    for (uint32_t t = 0; t < count; ++t)
        for (int v = 0; v < 3; ++v) sorted[3 * t + v] = mesh.indices[3 * order[t] + v];
    mesh.indices = std::move(sorted);
}

}  // namespace caustics::bench
