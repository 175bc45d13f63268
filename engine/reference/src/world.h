#pragma once
// The scene flattened to world space for the reference tracer: one triangle list with per-vertex
// shading normals and a material per triangle, plus the BVH over it.
#include <cstdint>
#include <memory>
#include <vector>

#include "caustics/reference/bvh.h"
#include "caustics/rhi/result.h"
#include "caustics/scene/scene.h"

namespace caustics::reference {

struct Sphere {
    glm::vec3 centre{0.0f};
    float radius = 0.0f;
};

struct WorldScene {
    std::vector<Triangle> triangles;
    std::vector<glm::vec3> normals;      // 3 per triangle (unit, world space)
    std::vector<uint32_t> materials;     // per triangle
    std::vector<glm::vec2> uvs;          // 3 per triangle ((0,0) where the mesh has none)
    std::unique_ptr<TriangleBvh> bvh;
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};
    glm::vec3 specularMin{0.0f}, specularMax{0.0f};
    bool hasSpecular = false;
};

WorldScene buildWorldScene(const scene::Scene& scene);

// Linear albedo of `material` at `uv`: baseColor times its base-colour texture sampled as the GPU
// passes do (bilinear, repeat, sRGB decoded, mip 0: sceneBaseColor in shaders/common/scene_resources.h).
glm::vec3 albedoAt(const scene::Scene& scene, const scene::Material& material, glm::vec2 uv);

// Offset for rays leaving a surface point, relative to the coordinates' magnitude (float spacing).
inline float rayEpsilon(const glm::vec3& p) {
    return 1e-4f * (1.0f + glm::max(glm::abs(p.x), glm::max(glm::abs(p.y), glm::abs(p.z))));
}

// The surface a ray (origin + t dir) hit: shading normal interpolated from the vertices, geometric
// normal turned to the shading normal's side (the authored normals say which side is outside).
struct SurfacePoint {
    glm::vec3 position;
    glm::vec3 shadingNormal;
    glm::vec3 geometricNormal;
    const scene::Material* material;
    glm::vec3 albedo;   // linear, base colour x texture (albedoAt)
};
SurfacePoint surfaceAt(const scene::Scene& scene, const WorldScene& world, const glm::vec3& origin,
                       const glm::vec3& dir, const RayHit& hit);

// Refuses what the reference renderers cannot trace (empty image, degenerate camera, indices or
// material indices out of range), naming `who` and the mesh.
Status checkReferenceInputs(const char* who, const scene::Scene& scene, const scene::Camera& camera, uint32_t width,
                            uint32_t height);

Sphere boundingSphere(const glm::vec3& min, const glm::vec3& max);

}  // namespace caustics::reference
