#pragma once
// CPU reference for the ray-tracing GPU tests: Moeller-Trumbore ray/triangle intersection (Moeller &
// Trumbore 1997, "Fast, minimum storage ray-triangle intersection") in double precision over
// instanced triangle meshes, reporting the closest hit and whether the ray passes so close to an
// edge (or to another hit at the same distance) that a float GPU traversal may legitimately differ.
#include <array>
#include <cstdint>
#include <vector>

#include "caustics/rhi/accel_struct.h"

namespace caustics::test {

using Vec3 = std::array<double, 3>;

struct CpuMesh {
    std::vector<float> positions;    // xyz per vertex
    std::vector<uint32_t> indices;   // three per triangle
    uint32_t triangleCount() const { return uint32_t(indices.size() / 3); }
};

// Row-major 3x4 transform, as in rhi::InstanceDesc.
using Transform = std::array<std::array<float, 4>, 3>;
Transform makeTransform(double rotX, double rotY, double rotZ, Vec3 scale, Vec3 translation);
void writeTransform(const Transform& t, rhi::InstanceDesc& instance);

struct CpuInstance {
    const CpuMesh* mesh = nullptr;
    Transform transform{};
    uint32_t instanceId = 0;
};

struct CpuHit {
    bool hit = false;
    uint32_t instanceId = ~0u;
    uint32_t primitiveId = ~0u;
    double t = 0;
    // The ray passes within the barycentric epsilon of an edge of some triangle it (nearly) hits, or two
    // hits lie at nearly the same distance: the GPU answer may differ here without being wrong.
    bool ambiguous = false;
};

// Closest hit in [tMin, tMax] over `candidates` (indices into `instances`; empty = all).
CpuHit traceCpu(const std::vector<CpuInstance>& instances, const Vec3& origin, const Vec3& direction,
                double tMin, double tMax, double edgeEpsilon, const std::vector<uint32_t>& candidates = {});

// A height-field grid over [-1, 1]^2 (z = amplitude * sin(3x) cos(2y)), two triangles per cell, with
// no two triangles at the same depth along any straight line parallel to z.
CpuMesh makeTerrain(uint32_t cells, float amplitude);
// The quad [-h, h]^2 at z = 0 as two triangles (0,1,2) and (0,2,3).
CpuMesh makeQuad(float halfSize);

}  // namespace caustics::test
