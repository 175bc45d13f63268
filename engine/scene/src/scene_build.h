#pragma once
// Private helpers for the generated scenes.
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "caustics/scene/scene.h"

namespace caustics::scene::build {

inline uint32_t addMaterial(Scene& scene, Material material) {
    scene.materials.push_back(std::move(material));
    return uint32_t(scene.materials.size() - 1);
}

inline uint32_t addTexture(Scene& scene, Texture texture, std::string name) {
    texture.name = std::move(name);
    scene.textures.push_back(std::move(texture));
    return uint32_t(scene.textures.size() - 1);
}

// Adds the mesh with its material and one instance; objectId = instance index + 1 (0 = none).
inline uint32_t addObject(Scene& scene, Mesh mesh, uint32_t material, std::string name,
                          const glm::mat4& transform = glm::mat4(1.0f)) {
    mesh.material = material;
    mesh.name = std::move(name);
    scene.meshes.push_back(std::move(mesh));
    uint32_t id = uint32_t(scene.instances.size());
    scene.instances.push_back({uint32_t(scene.meshes.size() - 1), transform, id + 1});
    return id;
}

inline Material diffuse(std::string name, const glm::vec3& color, int32_t texture = -1, float roughness = 0.8f) {
    Material m;
    m.name = std::move(name);
    m.baseColor = color;
    m.baseColorTexture = texture;
    m.roughness = roughness;
    return m;
}

// Clear dielectric (KHR_materials_transmission = 1, roughness 0). thickness > 0 marks a volume.
inline Material dielectric(std::string name, float ior, float thickness, const glm::vec3& attenuationColor = glm::vec3(1.0f),
                           float attenuationDistance = 0.0f) {
    Material m;
    m.name = std::move(name);
    m.baseColor = glm::vec3(1.0f);
    m.roughness = 0.0f;
    m.transmission = 1.0f;
    m.ior = ior;
    m.thickness = thickness;
    m.attenuationColor = attenuationColor;
    m.attenuationDistance = attenuationDistance;
    return m;
}

inline Material metal(std::string name, const glm::vec3& color, float roughness) {
    Material m;
    m.name = std::move(name);
    m.baseColor = color;
    m.metallic = 1.0f;
    m.roughness = roughness;
    return m;
}

inline Light spotLight(std::string name, const glm::vec3& position, const glm::vec3& target, float candela,
                       float innerCone, float outerCone, const glm::vec3& color = glm::vec3(1.0f)) {
    Light l;
    l.name = std::move(name);
    l.type = LightType::Spot;
    l.position = position;
    l.direction = glm::normalize(target - position);
    l.intensity = candela;
    l.innerConeAngle = innerCone;
    l.outerConeAngle = outerCone;
    l.color = color;
    return l;
}

inline Camera lookAt(const glm::vec3& eye, const glm::vec3& target, float fovRadians) {
    Camera c;
    c.eye = eye;
    c.target = target;
    c.verticalFovRadians = fovRadians;
    return c;
}

}  // namespace caustics::scene::build
