#ifndef CAUSTICS_COMMON_SCENE_H
#define CAUSTICS_COMMON_SCENE_H
// The GPU scene's tables as every pass's shaders see them, named once in the shared dialect
// (docs/shaders.md, "Scene API"): the layouts of caustics::scene::GpuMaterial / GpuInstance /
// GpuVertex (engine/scene/include/caustics/scene/gpu_types.h) and caustics::GpuLight
// (passes/internal/caustics/gpu_light.h), their flags, and the pure functions of a material. The C++
// tables are checked against these member by member (passes/module/scene_layout_check.cpp). The
// resources are declared once in C++ (passes/module/scene_set_bindings.h, generated as bindings/scene.h);
// common/scene_resources.h defines over them the accessors sceneSurfaceHit (a ray hit's surface) reads.
#include "common/fresnel.h"
#include "common/lang.h"
#include "common/specular_event.h"

CAUSTICS_SHARED_BEGIN
// GpuMaterial::flags.
CAUSTICS_CONST uint kMaterialSpecular = 1u;
CAUSTICS_CONST uint kMaterialTransmissive = 2u;
CAUSTICS_CONST uint kMaterialMetallic = 4u;
CAUSTICS_CONST uint kMaterialDoubleSided = 8u;
CAUSTICS_CONST uint kMaterialThinWalled = 16u;
// GpuInstance::flags.
CAUSTICS_CONST uint kInstanceSpecular = 1u;
// TLAS instance masks (engine/scene/include/caustics/scene/gpu_scene.h).
CAUSTICS_CONST uint kMaskDiffuse = 0x1u;
CAUSTICS_CONST uint kMaskSpecular = 0x2u;
// GpuLight::type.
CAUSTICS_CONST uint kLightPoint = 0u;
CAUSTICS_CONST uint kLightSpot = 1u;
CAUSTICS_CONST uint kLightDirectional = 2u;

struct GpuMaterial {   // 96 bytes
    float3 baseColor;        float metallic;
    float3 specularColor;    float roughness;
    float3 attenuationColor; float attenuationDistance;
    float3 emissive;         float ior;
    float transmission; float specular; float thickness; int baseColorTexture;
    uint flags; uint pad0; uint pad1; uint pad2;
};

struct GpuInstance {   // 160 bytes
    float4x4 objectToWorld;
    float4x4 normalToWorld;   // transpose(inverse(objectToWorld)) in the upper 3x3
    uint material; uint firstVertex; uint firstIndex; uint triangleCount;
    uint objectId; uint mesh; uint flags; uint pad;
};

struct GpuVertex {     // 48 bytes; positions live in their own float array (the BLAS input)
    float3 normal; float u;
    float4 tangent;
    float v; float pad0; float pad1; float pad2;
};

struct GpuLight {      // 64 bytes
    float3 position;  uint type;
    float3 direction; float range;      // direction: where the light shines; range 0 = infinite
    float3 intensity; float cosInner;   // colour x intensity: candela (point/spot) or lux (directional)
    float cosOuter; uint castsCaustics; uint pad0; uint pad1;
};

struct GpuLightTableHeader {   // 16 bytes, before the lights (caustics::packLightBuffer)
    uint count; uint pad0; uint pad1; uint pad2;
};

// Everything a pass needs about a ray hit on a scene triangle (sceneSurfaceHit fills it).
struct SurfaceHit {
    float3 position;         // world
    float3 geometricNormal;  // world, unit, from the triangle's winding (not flipped)
    float3 shadingNormal;    // world, unit, interpolated vertex normal (not flipped)
    float2 uv;
    float3 baseColor;        // linear, factor x texture
    uint instance;           // instance index
    uint objectId;           // instance index + 1, as the G-buffer stores it
    GpuMaterial material;
    OpticalMaterial optics;  // for common/specular_event.h
};

CAUSTICS_FN bool sceneMaterialIsSpecular(GpuMaterial m) { return (m.flags & kMaterialSpecular) != 0u; }

// The G-buffer's optics encoding (caustics/gbuffer.h): x reflectance weight, y transmittance weight,
// z IOR, w specular flag.
CAUSTICS_FN float4 sceneOpticsEncoding(GpuMaterial m) {
    float reflectance = m.metallic + (1.0f - m.metallic) * m.specular * dielectricF0(m.ior);
    float transmittance = (1.0f - m.metallic) * m.transmission;
    return float4(reflectance, transmittance, m.ior, sceneMaterialIsSpecular(m) ? 1.0f : 0.0f);
}
CAUSTICS_SHARED_END

// The accessors sceneSurfaceHit reads the scene through: defined over the generated declarations by
// common/scene_resources.h, or by a C++ caller.
CAUSTICS_SHARED_BEGIN
GpuInstance sceneInstance(uint i);
GpuVertex sceneVertex(uint i);
GpuMaterial sceneMaterial(uint i);
uint sceneIndex(uint i);
float3 scenePosition(uint vertex);
float3 sceneBaseColor(GpuMaterial m, float2 uv);
CAUSTICS_SHARED_END

CAUSTICS_SHARED_BEGIN
// The scene vertex indices of triangle `primitive` of instance `inst` (its index range is relative to
// firstVertex).
CAUSTICS_FN uint3 sceneTriangle(GpuInstance inst, uint primitive) {
    uint base = inst.firstIndex + 3u * primitive;
    return uint3(inst.firstVertex + sceneIndex(base), inst.firstVertex + sceneIndex(base + 1u),
                 inst.firstVertex + sceneIndex(base + 2u));
}

// instance: the hit's instance index (GLSL gl_InstanceCustomIndexEXT, HLSL InstanceID()); primitive:
// its triangle; barycentrics: the hit attribute (b1, b2), weights (1 - b1 - b2, b1, b2).
CAUSTICS_FN SurfaceHit sceneSurfaceHit(uint instance, uint primitive, float2 barycentrics) {
    GpuInstance inst = sceneInstance(instance);
    uint3 tri = sceneTriangle(inst, primitive);
    uint i0 = tri.x, i1 = tri.y, i2 = tri.z;
    float3 w = float3(1.0f - barycentrics.x - barycentrics.y, barycentrics.x, barycentrics.y);

    float3 p0 = scenePosition(i0), p1 = scenePosition(i1), p2 = scenePosition(i2);
    GpuVertex v0 = sceneVertex(i0), v1 = sceneVertex(i1), v2 = sceneVertex(i2);

    SurfaceHit h;
    float3 pObject = w.x * p0 + w.y * p1 + w.z * p2;
    h.position = toFloat3(mat4Mul(inst.objectToWorld, float4(pObject, 1.0f)));
    h.geometricNormal = normalize(mat3Mul(inst.normalToWorld, cross(p1 - p0, p2 - p0)));
    float3 ns = w.x * v0.normal + w.y * v1.normal + w.z * v2.normal;
    h.shadingNormal = dot(ns, ns) > 1e-12f ? normalize(mat3Mul(inst.normalToWorld, ns)) : h.geometricNormal;
    h.uv = w.x * float2(v0.u, v0.v) + w.y * float2(v1.u, v1.v) + w.z * float2(v2.u, v2.v);
    h.instance = instance;
    h.objectId = instance + 1u;
    h.material = sceneMaterial(inst.material);
    h.baseColor = sceneBaseColor(h.material, h.uv);
    h.optics.baseColor = h.baseColor;
    h.optics.metallic = h.material.metallic;
    h.optics.roughness = h.material.roughness;
    h.optics.transmission = h.material.transmission;
    h.optics.ior = h.material.ior;
    h.optics.thinWalled = (h.material.flags & kMaterialThinWalled) != 0u;
    return h;
}
CAUSTICS_SHARED_END


#endif  // CAUSTICS_COMMON_SCENE_H
