#pragma once
// CPU-side scene: what a glTF file or a built-in generator produces, and what the GPU scene, the
// caustic passes and the CPU reference light tracer consume. World space, metres, right-handed, +Y up.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace caustics::scene {

// Optical properties the caustic passes need (docs/physics.md), derived from glTF PBR
// metallic-roughness + KHR_materials_transmission/ior/volume/specular.
struct Material {
    std::string name;
    glm::vec3 baseColor{0.8f};
    int32_t baseColorTexture = -1;    // index into Scene::textures, -1 = none
    float metallic = 0.0f;
    float roughness = 1.0f;
    float transmission = 0.0f;        // KHR_materials_transmission
    float ior = 1.5f;                 // KHR_materials_ior
    float specular = 1.0f;            // KHR_materials_specular factor
    glm::vec3 specularColor{1.0f};
    float thickness = 0.0f;           // KHR_materials_volume: 0 = thin-walled
    glm::vec3 attenuationColor{1.0f};
    float attenuationDistance = 0.0f; // 0 = no absorption (infinite distance)
    glm::vec3 emissive{0.0f};
    bool doubleSided = false;

    // A surface is "specular" (can start or continue a caustic path) when it is smooth enough that
    // a delta/near-delta lobe dominates: metals and transmissive dielectrics below the roughness cut.
    static constexpr float kSpecularRoughnessLimit = 0.3f;
    bool isSpecular() const {
        return roughness <= kSpecularRoughnessLimit && (metallic > 0.5f || transmission > 0.0f);
    }
    // Thin-walled glass (glTF transmission without KHR_materials_volume): a pane of two parallel faces
    // that does not bend light (docs/physics.md "Thin-walled glass"). Opaque surfaces have no second face.
    bool isThinWalled() const { return transmission > 0.0f && thickness <= 0.0f; }
};

struct Texture {
    std::string name;
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba8;       // sRGB-encoded RGBA8, tightly packed
};

// One triangle mesh with one material; glTF primitives become separate meshes.
struct Mesh {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;        // empty if absent
    std::vector<glm::vec4> tangents;   // empty if absent
    std::vector<uint32_t> indices;     // triangle list
    uint32_t material = 0;
};

struct Instance {
    uint32_t mesh = 0;
    glm::mat4 transform{1.0f};         // object -> world
    uint32_t objectId = 0;             // unique per instance; identifies surfaces in the passes
};

enum class LightType : uint8_t { Point, Spot, Directional };

struct Light {
    std::string name;
    LightType type = LightType::Point;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, -1.0f, 0.0f};   // the light shines along this (spot, directional)
    glm::vec3 color{1.0f};
    // KHR_lights_punctual units: point/spot intensity in candela (lm/sr), directional in lux (lm/m^2).
    float intensity = 1.0f;
    float range = 0.0f;                       // 0 = infinite
    float innerConeAngle = 0.0f;              // radians (spot)
    float outerConeAngle = 0.785398f;         // radians (spot)
};

struct Camera {
    glm::vec3 eye{0.0f, 1.0f, 3.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float verticalFovRadians = 0.785398f;
    float nearPlane = 0.05f;
    float farPlane = 200.0f;
};

struct Scene {
    std::string name;
    bool isStandIn = false;            // a generated stand-in for a real asset (say so in outputs)
    // Added by the scene helper: linear multiplier on radiance before tone mapping that the scene's
    // author chose so that the image is well exposed (built-in scenes set it; glTF files keep 1).
    float exposure = 1.0f;
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<Texture> textures;
    std::vector<Instance> instances;
    std::vector<Light> lights;
    std::vector<Camera> cameras;       // the first one is the default view
};

}  // namespace caustics::scene
