#include "world.h"

#include <cmath>

#include <limits>
#include <string>

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
            for (int k = 0; k < 3; ++k) {
                uint32_t idx = mesh.indices[i + k];
                w.uvs.push_back(idx < mesh.uvs.size() ? mesh.uvs[idx] : glm::vec2(0.0f));
            }
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

namespace {
// IEC 61966-2-1 sRGB transfer function, decoding one 8-bit channel.
float srgbToLinear(uint8_t encoded) {
    float c = float(encoded) / 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}
glm::vec3 texel(const scene::Texture& t, int x, int y) {
    x = ((x % int(t.width)) + int(t.width)) % int(t.width);
    y = ((y % int(t.height)) + int(t.height)) % int(t.height);
    const uint8_t* p = &t.rgba8[(size_t(y) * t.width + size_t(x)) * 4];
    return {srgbToLinear(p[0]), srgbToLinear(p[1]), srgbToLinear(p[2])};
}
}  // namespace

glm::vec3 albedoAt(const scene::Scene& scene, const scene::Material& material, glm::vec2 uv) {
    glm::vec3 albedo = material.baseColor;
    if (material.baseColorTexture < 0 || size_t(material.baseColorTexture) >= scene.textures.size()) return albedo;
    const scene::Texture& t = scene.textures[size_t(material.baseColorTexture)];
    if (t.width == 0 || t.height == 0 || t.rgba8.size() < size_t(t.width) * t.height * 4) return albedo;
    // Texel centres at half-integers (Vulkan spec 16.6 "Texel Filtering", linear filter).
    float fx = uv.x * float(t.width) - 0.5f, fy = uv.y * float(t.height) - 0.5f;
    int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
    float ax = fx - float(x0), ay = fy - float(y0);
    glm::vec3 top = glm::mix(texel(t, x0, y0), texel(t, x0 + 1, y0), ax);
    glm::vec3 bottom = glm::mix(texel(t, x0, y0 + 1), texel(t, x0 + 1, y0 + 1), ax);
    return albedo * glm::mix(top, bottom, ay);
}

SurfacePoint surfaceAt(const scene::Scene& scene, const WorldScene& world, const glm::vec3& origin,
                       const glm::vec3& dir, const RayHit& hit) {
    const Triangle& tri = world.triangles[hit.triangle];
    const glm::vec3 w(1.0f - hit.u - hit.v, hit.u, hit.v);
    const glm::vec3* vn = &world.normals[size_t(hit.triangle) * 3];
    const glm::vec2* uv = &world.uvs[size_t(hit.triangle) * 3];
    SurfacePoint s;
    s.position = origin + hit.t * dir;
    s.shadingNormal = glm::normalize(w.x * vn[0] + w.y * vn[1] + w.z * vn[2]);
    s.geometricNormal = glm::normalize(glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0));
    if (glm::dot(s.shadingNormal, s.geometricNormal) < 0.0f) s.geometricNormal = -s.geometricNormal;
    s.material = &scene.materials[world.materials[hit.triangle]];
    s.albedo = albedoAt(scene, *s.material, w.x * uv[0] + w.y * uv[1] + w.z * uv[2]);
    return s;
}

Status checkReferenceInputs(const char* who, const scene::Scene& scene, const scene::Camera& camera, uint32_t width,
                            uint32_t height) {
    const std::string name(who);
    if (width == 0 || height == 0) return makeError(name + ": image size is zero");
    if (glm::length(camera.target - camera.eye) <= 0.0f) return makeError(name + ": camera eye and target coincide");
    for (const scene::Mesh& mesh : scene.meshes) {
        if (mesh.material >= scene.materials.size())
            return makeError(name + ": mesh '" + mesh.name + "' has material index " + std::to_string(mesh.material) +
                             " out of range");
        for (uint32_t idx : mesh.indices)
            if (idx >= mesh.positions.size()) return makeError(name + ": mesh '" + mesh.name + "' has an index out of range");
    }
    return okStatus();
}

}  // namespace caustics::reference
