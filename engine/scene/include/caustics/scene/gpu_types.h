#pragma once
// GPU-side tables of the scene, laid out for GLSL std430 storage buffers (and HLSL
// StructuredBuffer with the same 16-byte-aligned members). The static_asserts pin every offset; a
// shader-side declaration must match them member for member:
//
//   struct GpuMaterial {            // 96 bytes
//       vec3 baseColor;     float metallic;           //  0
//       vec3 specularColor; float roughness;          // 16
//       vec3 attenuationColor; float attenuationDistance;  // 32
//       vec3 emissive;      float ior;                // 48
//       float transmission; float specular; float thickness; int baseColorTexture;   // 64
//       uint flags; uint pad0; uint pad1; uint pad2;  // 80
//   };
//   struct GpuInstance {            // 160 bytes
//       mat4 objectToWorld;                           //  0
//       mat4 normalToWorld;   (transpose(inverse(M)) in the upper 3x3, column 3 = 0)   // 64
//       uint material; uint firstVertex; uint firstIndex; uint triangleCount;          // 128
//       uint objectId; uint mesh; uint flags; uint pad;                                // 144
//   };
//   struct GpuVertex {              // 48 bytes (positions live in their own float3 array)
//       vec3 normal; float u;  vec4 tangent;  float v; float pad0, pad1, pad2;
//   };
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include "caustics/scene/scene.h"

namespace caustics::scene {

enum GpuMaterialFlags : uint32_t {
    kMaterialSpecular = 1u << 0,      // Material::isSpecular()
    kMaterialTransmissive = 1u << 1,  // transmission > 0
    kMaterialMetallic = 1u << 2,      // metallic > 0.5
    kMaterialDoubleSided = 1u << 3,
    kMaterialThinWalled = 1u << 4,    // transmissive with thickness 0 (KHR_materials_volume absent)
};

struct GpuMaterial {
    glm::vec3 baseColor{0.8f};
    float metallic = 0.0f;
    glm::vec3 specularColor{1.0f};
    float roughness = 1.0f;
    glm::vec3 attenuationColor{1.0f};
    float attenuationDistance = 0.0f;   // 0 = no absorption
    glm::vec3 emissive{0.0f};
    float ior = 1.5f;
    float transmission = 0.0f;
    float specular = 1.0f;
    float thickness = 0.0f;
    int32_t baseColorTexture = -1;      // index into the bindless texture array, -1 = none
    uint32_t flags = 0;
    uint32_t pad0 = 0, pad1 = 0, pad2 = 0;
};
static_assert(sizeof(GpuMaterial) == 96);
static_assert(offsetof(GpuMaterial, metallic) == 12);
static_assert(offsetof(GpuMaterial, specularColor) == 16);
static_assert(offsetof(GpuMaterial, roughness) == 28);
static_assert(offsetof(GpuMaterial, attenuationColor) == 32);
static_assert(offsetof(GpuMaterial, emissive) == 48);
static_assert(offsetof(GpuMaterial, ior) == 60);
static_assert(offsetof(GpuMaterial, transmission) == 64);
static_assert(offsetof(GpuMaterial, baseColorTexture) == 76);
static_assert(offsetof(GpuMaterial, flags) == 80);

enum GpuInstanceFlags : uint32_t {
    kInstanceSpecular = 1u << 0,   // its material is specular (also TLAS mask kMaskSpecular)
};

struct GpuInstance {
    glm::mat4 objectToWorld{1.0f};
    glm::mat4 normalToWorld{1.0f};
    uint32_t material = 0;
    uint32_t firstVertex = 0;     // into the positions / vertex-attribute arrays
    uint32_t firstIndex = 0;      // into the index array; indices are relative to firstVertex
    uint32_t triangleCount = 0;
    uint32_t objectId = 0;
    uint32_t mesh = 0;
    uint32_t flags = 0;
    uint32_t pad = 0;
};
static_assert(sizeof(GpuInstance) == 160);
static_assert(offsetof(GpuInstance, normalToWorld) == 64);
static_assert(offsetof(GpuInstance, material) == 128);
static_assert(offsetof(GpuInstance, objectId) == 144);

struct GpuVertex {
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    float u = 0.0f;
    glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};
    float v = 0.0f;
    float pad0 = 0.0f, pad1 = 0.0f, pad2 = 0.0f;
};
static_assert(sizeof(GpuVertex) == 48);
static_assert(offsetof(GpuVertex, tangent) == 16);
static_assert(offsetof(GpuVertex, v) == 32);

GpuMaterial toGpuMaterial(const Material& material);
GpuInstance toGpuInstance(const Scene& scene, const Instance& instance, uint32_t firstVertex, uint32_t firstIndex);

}  // namespace caustics::scene
