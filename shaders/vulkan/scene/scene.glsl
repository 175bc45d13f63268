#ifndef CAUSTICS_SCENE_SCENE_GLSL
#define CAUSTICS_SCENE_SCENE_GLSL
// GLSL side of the GPU scene (engine/scene/include/scene/gpu_scene.h + gpu_types.h) as bound by
// caustics::SceneBindings (passes/include/caustics/scene_bindings.h): one descriptor set, by default
// set 0 (define SCENE_SET before including to move it). Usable from raster, compute and every
// ray-tracing stage. Define SCENE_NO_TEXTURES to leave the texture array out of a shader, and
// SCENE_UNIFORM_TEXTURE_INDEX where the material is dynamically uniform (one draw per instance), which
// drops the nonuniformEXT qualifier (and its SampledImageArrayNonUniformIndexing capability).
// Raster and compute shaders without ray queries must define SCENE_NO_TLAS (an acceleration-structure
// type is invalid SPIR-V without a ray-tracing capability).
//
//   binding 0  accelerationStructureEXT  sceneTlas        instanceId = instance index
//   binding 1  float[]                   scenePositions   3 floats per vertex (BLAS input)
//   binding 2  GpuVertex[]               sceneVertices    normal, uv, tangent
//   binding 3  uint[]                    sceneIndices     relative to the instance's firstVertex
//   binding 4  GpuMaterial[]             sceneMaterials
//   binding 5  GpuInstance[]             sceneInstances
//   binding 6  lights header + GpuLight[] (caustics/gpu_light.h)
//   binding 7  sampler                   sceneSampler     linear, repeat
//   binding 8  texture2D[SCENE_MAX_TEXTURES] sceneTextures RGBA8_SRGB (unused slots: white 1x1)
#ifndef SCENE_NO_TLAS
#extension GL_EXT_ray_tracing : enable
#endif
#extension GL_EXT_nonuniform_qualifier : enable
#include "common/lang.h"
#include "common/fresnel.h"
#include "common/specular_event.h"

#ifndef SCENE_SET
#define SCENE_SET 0
#endif
// Must equal caustics::kMaxSceneTextures.
#define SCENE_MAX_TEXTURES 256

// gpu_types.h flags.
const uint kMaterialSpecular = 1u;
const uint kMaterialTransmissive = 2u;
const uint kMaterialMetallic = 4u;
const uint kMaterialDoubleSided = 8u;
const uint kMaterialThinWalled = 16u;
const uint kInstanceSpecular = 1u;
// TLAS instance masks (gpu_scene.h).
const uint kMaskDiffuse = 0x1u;
const uint kMaskSpecular = 0x2u;

struct GpuMaterial {
    vec3 baseColor;        float metallic;
    vec3 specularColor;    float roughness;
    vec3 attenuationColor; float attenuationDistance;
    vec3 emissive;         float ior;
    float transmission; float specular; float thickness; int baseColorTexture;
    uint flags; uint pad0; uint pad1; uint pad2;
};

struct GpuInstance {
    mat4 objectToWorld;
    mat4 normalToWorld;
    uint material; uint firstVertex; uint firstIndex; uint triangleCount;
    uint objectId; uint mesh; uint flags; uint pad;
};

struct GpuVertex {
    vec3 normal; float u;
    vec4 tangent;
    float v; float pad0; float pad1; float pad2;
};

// caustics::GpuLight (passes/include/caustics/gpu_light.h), 64 bytes.
const uint kLightPoint = 0u;
const uint kLightSpot = 1u;
const uint kLightDirectional = 2u;
struct GpuLight {
    vec3 position;  uint type;
    vec3 direction; float range;       // direction: where the light shines; range 0 = infinite
    vec3 intensity; float cosInner;    // colour x intensity: candela (point/spot) or lux (directional)
    float cosOuter; uint castsCaustics; uint pad0; uint pad1;
};

#ifndef SCENE_NO_TLAS
layout(set = SCENE_SET, binding = 0) uniform accelerationStructureEXT sceneTlas;
#endif
layout(set = SCENE_SET, binding = 1, std430) readonly buffer ScenePositions { float scenePositions[]; };
layout(set = SCENE_SET, binding = 2, std430) readonly buffer SceneVertices { GpuVertex sceneVertices[]; };
layout(set = SCENE_SET, binding = 3, std430) readonly buffer SceneIndices { uint sceneIndices[]; };
layout(set = SCENE_SET, binding = 4, std430) readonly buffer SceneMaterials { GpuMaterial sceneMaterials[]; };
layout(set = SCENE_SET, binding = 5, std430) readonly buffer SceneInstances { GpuInstance sceneInstances[]; };
layout(set = SCENE_SET, binding = 6, std430) readonly buffer SceneLights {
    uint sceneLightCount; uint sceneLightPad0; uint sceneLightPad1; uint sceneLightPad2;
    GpuLight sceneLights[];
};
#ifndef SCENE_NO_TEXTURES
layout(set = SCENE_SET, binding = 7) uniform sampler sceneSampler;
layout(set = SCENE_SET, binding = 8) uniform texture2D sceneTextures[SCENE_MAX_TEXTURES];
#endif

vec3 scenePosition(uint vertex) {
    return vec3(scenePositions[3 * vertex], scenePositions[3 * vertex + 1], scenePositions[3 * vertex + 2]);
}

// Linear base colour of a material at uv (texture is sRGB-encoded; the sampler decodes it). The index
// is non-uniform in hit shaders, hence nonuniformEXT.
vec3 sceneBaseColor(GpuMaterial m, vec2 uv) {
    vec3 c = m.baseColor;
#ifndef SCENE_NO_TEXTURES
    if (m.baseColorTexture >= 0) {
        int t = m.baseColorTexture;
#ifdef SCENE_UNIFORM_TEXTURE_INDEX
        c *= textureLod(sampler2D(sceneTextures[t], sceneSampler), uv, 0.0).rgb;
#else
        c *= textureLod(sampler2D(sceneTextures[nonuniformEXT(t)], sceneSampler), uv, 0.0).rgb;
#endif
    }
#endif
    return c;
}

// Everything a pass needs about a ray hit on a scene triangle.
struct SurfaceHit {
    vec3 position;         // world
    vec3 geometricNormal;  // world, unit, from the triangle's winding (not flipped)
    vec3 shadingNormal;    // world, unit, interpolated vertex normal (not flipped)
    vec2 uv;
    vec3 baseColor;        // linear, factor x texture
    uint instance;         // instance index
    uint objectId;         // instance index + 1, as the G-buffer stores it
    GpuMaterial material;
    OpticalMaterial optics;  // for common/specular_event.h
};

// instance: gl_InstanceCustomIndexEXT (== instance index); primitive: gl_PrimitiveID;
// barycentrics: the hit attribute (b1, b2), weights (1 - b1 - b2, b1, b2).
SurfaceHit sceneSurfaceHit(uint instance, uint primitive, vec2 barycentrics) {
    GpuInstance inst = sceneInstances[instance];
    uint base = inst.firstIndex + 3u * primitive;
    uint i0 = inst.firstVertex + sceneIndices[base];
    uint i1 = inst.firstVertex + sceneIndices[base + 1u];
    uint i2 = inst.firstVertex + sceneIndices[base + 2u];
    vec3 w = vec3(1.0 - barycentrics.x - barycentrics.y, barycentrics.x, barycentrics.y);

    vec3 p0 = scenePosition(i0), p1 = scenePosition(i1), p2 = scenePosition(i2);
    GpuVertex v0 = sceneVertices[i0], v1 = sceneVertices[i1], v2 = sceneVertices[i2];

    SurfaceHit h;
    vec3 pObject = w.x * p0 + w.y * p1 + w.z * p2;
    h.position = (inst.objectToWorld * vec4(pObject, 1.0)).xyz;
    mat3 n2w = mat3(inst.normalToWorld);
    h.geometricNormal = normalize(n2w * cross(p1 - p0, p2 - p0));
    vec3 ns = w.x * v0.normal + w.y * v1.normal + w.z * v2.normal;
    h.shadingNormal = dot(ns, ns) > 1e-12 ? normalize(n2w * ns) : h.geometricNormal;
    h.uv = w.x * vec2(v0.u, v0.v) + w.y * vec2(v1.u, v1.v) + w.z * vec2(v2.u, v2.v);
    h.instance = instance;
    h.objectId = instance + 1u;
    h.material = sceneMaterials[inst.material];
    h.baseColor = sceneBaseColor(h.material, h.uv);
    h.optics.baseColor = h.baseColor;
    h.optics.metallic = h.material.metallic;
    h.optics.roughness = h.material.roughness;
    h.optics.transmission = h.material.transmission;
    h.optics.ior = h.material.ior;
    h.optics.thinWalled = (h.material.flags & kMaterialThinWalled) != 0u;
    return h;
}

bool sceneMaterialIsSpecular(GpuMaterial m) { return (m.flags & kMaterialSpecular) != 0u; }

// The G-buffer's optics encoding (caustics/gbuffer.h): x reflectance weight, y transmittance weight,
// z IOR, w specular flag.
vec4 sceneOpticsEncoding(GpuMaterial m) {
    float reflectance = m.metallic + (1.0 - m.metallic) * m.specular * dielectricF0(m.ior);
    float transmittance = (1.0 - m.metallic) * m.transmission;
    return vec4(reflectance, transmittance, m.ior, sceneMaterialIsSpecular(m) ? 1.0 : 0.0);
}

#endif
