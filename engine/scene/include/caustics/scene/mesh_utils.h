#pragma once
// Geometry helpers over the CPU scene: bounds, triangle counts, normal generation and the spatial
// (Morton) triangle sort that BLAS builders need (lavapipe traces random-order triangles
// 10-17x slower because its builder splits the index range in order).
#include <cstdint>
#include <limits>

#include <glm/glm.hpp>

#include "caustics/scene/scene.h"

namespace caustics::scene {

struct Aabb {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{-std::numeric_limits<float>::max()};

    bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    void extend(const glm::vec3& p) { min = glm::min(min, p); max = glm::max(max, p); }
    void extend(const Aabb& b) { if (!b.empty()) { extend(b.min); extend(b.max); } }
    glm::vec3 center() const { return 0.5f * (min + max); }
    glm::vec3 extent() const { return empty() ? glm::vec3(0.0f) : max - min; }
    bool contains(const glm::vec3& p) const {
        return p.x >= min.x && p.y >= min.y && p.z >= min.z && p.x <= max.x && p.y <= max.y && p.z <= max.z;
    }
};

uint64_t triangleCount(const Mesh& mesh);
// Triangles of all instances (a mesh instanced twice counts twice): what the TLAS traces.
uint64_t triangleCount(const Scene& scene);
Aabb meshBounds(const Mesh& mesh);
// Bounds of the eight corners of `box` transformed by `transform`.
Aabb transformBounds(const Aabb& box, const glm::mat4& transform);
Aabb instanceBounds(const Scene& scene, const Instance& instance);
Aabb sceneBounds(const Scene& scene);
// World-space bounds of every instance whose material isSpecular() (empty box if none): the region
// a light's caustic map must cover; lights whose frustum misses it are skipped by the passes.
Aabb specularBounds(const Scene& scene);
bool isSpecularInstance(const Scene& scene, const Instance& instance);

// Fills mesh.normals. smooth = area-weighted vertex normals over shared vertices; flat = each
// triangle gets its own three vertices with the face normal (glTF 2.0 3.7.2.1: "When normals are not
// specified, client implementations MUST calculate flat normals").
void generateNormals(Mesh& mesh, bool smooth);

// 30-bit Morton code (10 bits per axis) of a point already normalised to [0,1]^3.
uint32_t mortonCode(const glm::vec3& unitPosition);
// Reorders the triangles (index triples) by the Morton code of their centroids within the mesh
// bounds. Vertices are untouched, so the set of triangles is unchanged.
void sortTrianglesMorton(Mesh& mesh);
void sortTrianglesMorton(Scene& scene);

// The 3x3 matrix that transforms normals: transpose(inverse(upper 3x3)).
glm::mat3 normalMatrix(const glm::mat4& transform);

}  // namespace caustics::scene
