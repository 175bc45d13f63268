#include "caustics/scene/mesh_utils.h"

#include <algorithm>
#include <numeric>

namespace caustics::scene {

uint64_t triangleCount(const Mesh& mesh) { return mesh.indices.size() / 3; }

uint64_t triangleCount(const Scene& scene) {
    uint64_t total = 0;
    for (const Instance& inst : scene.instances)
        if (inst.mesh < scene.meshes.size()) total += triangleCount(scene.meshes[inst.mesh]);
    return total;
}

Aabb meshBounds(const Mesh& mesh) {
    Aabb box;
    for (const glm::vec3& p : mesh.positions) box.extend(p);
    return box;
}

Aabb transformBounds(const Aabb& box, const glm::mat4& transform) {
    Aabb out;
    if (box.empty()) return out;
    for (int corner = 0; corner < 8; ++corner) {
        glm::vec3 p{(corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                    (corner & 4) ? box.max.z : box.min.z};
        out.extend(glm::vec3(transform * glm::vec4(p, 1.0f)));
    }
    return out;
}

Aabb instanceBounds(const Scene& scene, const Instance& instance) {
    if (instance.mesh >= scene.meshes.size()) return {};
    return transformBounds(meshBounds(scene.meshes[instance.mesh]), instance.transform);
}

Aabb sceneBounds(const Scene& scene) {
    Aabb box;
    for (const Instance& inst : scene.instances) box.extend(instanceBounds(scene, inst));
    return box;
}

bool isSpecularInstance(const Scene& scene, const Instance& instance) {
    if (instance.mesh >= scene.meshes.size()) return false;
    uint32_t m = scene.meshes[instance.mesh].material;
    return m < scene.materials.size() && scene.materials[m].isSpecular();
}

Aabb specularBounds(const Scene& scene) {
    Aabb box;
    for (const Instance& inst : scene.instances)
        if (isSpecularInstance(scene, inst)) box.extend(instanceBounds(scene, inst));
    return box;
}

void generateNormals(Mesh& mesh, bool smooth) {
    if (!smooth) {
        // Flat: unweld so every triangle owns its vertices.
        Mesh flat;
        flat.name = mesh.name;
        flat.material = mesh.material;
        size_t triCount = mesh.indices.size() / 3;
        flat.positions.reserve(triCount * 3);
        flat.normals.reserve(triCount * 3);
        for (size_t t = 0; t < triCount; ++t) {
            uint32_t i[3] = {mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]};
            glm::vec3 n = glm::cross(mesh.positions[i[1]] - mesh.positions[i[0]], mesh.positions[i[2]] - mesh.positions[i[0]]);
            float len = glm::length(n);
            n = len > 0.0f ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
            for (uint32_t k : i) {
                flat.indices.push_back(uint32_t(flat.positions.size()));
                flat.positions.push_back(mesh.positions[k]);
                flat.normals.push_back(n);
                if (!mesh.uvs.empty()) flat.uvs.push_back(mesh.uvs[k]);
                if (!mesh.tangents.empty()) flat.tangents.push_back(mesh.tangents[k]);
            }
        }
        mesh = std::move(flat);
        return;
    }
    // Smooth: the unnormalised cross product weights each face by twice its area.
    mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0f));
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        glm::vec3 n = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
        mesh.normals[a] += n;
        mesh.normals[b] += n;
        mesh.normals[c] += n;
    }
    for (glm::vec3& n : mesh.normals) {
        float len = glm::length(n);
        n = len > 0.0f ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
    }
}

// Spreads the low 10 bits of v so that there are two zero bits between each (bit-interleaving for
// a 3D Morton code; the classic "part1by2" magic-number sequence).
static uint32_t expandBits(uint32_t v) {
    v &= 0x3FFu;
    v = (v | (v << 16)) & 0x030000FFu;
    v = (v | (v << 8)) & 0x0300F00Fu;
    v = (v | (v << 4)) & 0x030C30C3u;
    v = (v | (v << 2)) & 0x09249249u;
    return v;
}

uint32_t mortonCode(const glm::vec3& unit) {
    glm::vec3 q = glm::clamp(unit, glm::vec3(0.0f), glm::vec3(1.0f)) * 1023.0f;
    return (expandBits(uint32_t(q.x)) << 2) | (expandBits(uint32_t(q.y)) << 1) | expandBits(uint32_t(q.z));
}

void sortTrianglesMorton(Mesh& mesh) {
    size_t triCount = mesh.indices.size() / 3;
    if (triCount < 2) return;
    Aabb box = meshBounds(mesh);
    glm::vec3 extent = glm::max(box.extent(), glm::vec3(1e-20f));
    std::vector<uint64_t> keys(triCount);   // code << 32 | triangle: a stable, deterministic order
    for (size_t t = 0; t < triCount; ++t) {
        glm::vec3 c = (mesh.positions[mesh.indices[3 * t]] + mesh.positions[mesh.indices[3 * t + 1]] +
                       mesh.positions[mesh.indices[3 * t + 2]]) / 3.0f;
        keys[t] = (uint64_t(mortonCode((c - box.min) / extent)) << 32) | uint64_t(t);
    }
    std::sort(keys.begin(), keys.end());
    std::vector<uint32_t> sorted(mesh.indices.size());
    for (size_t t = 0; t < triCount; ++t) {
        size_t src = size_t(keys[t] & 0xFFFFFFFFu);
        for (int k = 0; k < 3; ++k) sorted[3 * t + k] = mesh.indices[3 * src + k];
    }
    mesh.indices = std::move(sorted);
}

void sortTrianglesMorton(Scene& scene) {
    for (Mesh& mesh : scene.meshes) sortTrianglesMorton(mesh);
}

glm::mat3 normalMatrix(const glm::mat4& transform) {
    return glm::transpose(glm::inverse(glm::mat3(transform)));
}

}  // namespace caustics::scene
