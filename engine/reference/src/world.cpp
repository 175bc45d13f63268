#include "world.h"

#include <limits>

namespace caustics::reference {

WorldScene buildWorldScene(const scene::Scene& scene) {
    WorldScene w;
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    glm::vec3 slo = lo, shi = hi;
    for (const scene::Instance& inst : scene.instances) {
        if (inst.mesh >= scene.meshes.size()) continue;
        const scene::Mesh& mesh = scene.meshes[inst.mesh];
        bool specular = mesh.material < scene.materials.size() && scene.materials[mesh.material].isSpecular();
        // Normals transform with the inverse transpose (non-uniform scale).
        glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(inst.transform)));
        for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            Triangle tri;
            glm::vec3* p[3] = {&tri.p0, &tri.p1, &tri.p2};
            glm::vec3 n[3];
            for (int k = 0; k < 3; ++k) {
                uint32_t idx = mesh.indices[i + k];
                *p[k] = glm::vec3(inst.transform * glm::vec4(mesh.positions[idx], 1.0f));
                lo = glm::min(lo, *p[k]);
                hi = glm::max(hi, *p[k]);
                if (specular) { slo = glm::min(slo, *p[k]); shi = glm::max(shi, *p[k]); }
            }
            glm::vec3 geometric = glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
            if (glm::dot(geometric, geometric) == 0.0f) continue;  // degenerate: never hit
            geometric = glm::normalize(geometric);
            for (int k = 0; k < 3; ++k) {
                uint32_t idx = mesh.indices[i + k];
                n[k] = idx < mesh.normals.size() ? normalMatrix * mesh.normals[idx] : geometric;
                float len = glm::length(n[k]);
                n[k] = len > 0.0f ? n[k] / len : geometric;
            }
            w.triangles.push_back(tri);
            w.normals.insert(w.normals.end(), {n[0], n[1], n[2]});
            w.materials.push_back(mesh.material);
        }
    }
    w.boundsMin = lo;
    w.boundsMax = hi;
    w.hasSpecular = slo.x <= shi.x;
    w.specularMin = slo;
    w.specularMax = shi;
    w.bvh = std::make_unique<TriangleBvh>(w.triangles);
    return w;
}

Sphere boundingSphere(const glm::vec3& min, const glm::vec3& max) {
    return Sphere{0.5f * (min + max), 0.5f * glm::length(max - min)};
}

}  // namespace caustics::reference
