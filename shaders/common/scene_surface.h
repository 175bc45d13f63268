#ifndef CAUSTICS_COMMON_SCENE_SURFACE_H
#define CAUSTICS_COMMON_SCENE_SURFACE_H
// A ray hit's surface on a scene triangle, in the shared dialect (docs/shaders.md, "Scene API"). It
// reads the scene through the accessors the per-API scene shim defines before including this file
// (shaders/vulkan/scene/scene.glsl, shaders/d3d12/scene/scene.hlsli); a C++ caller defines them.
#include "common/scene.h"

#if defined(CAUSTICS_LANG_CPP)
namespace caustics::shader {
GpuInstance sceneInstance(uint i);
GpuVertex sceneVertex(uint i);
GpuMaterial sceneMaterial(uint i);
uint sceneIndex(uint i);
float3 scenePosition(uint vertex);
float3 sceneBaseColor(GpuMaterial m, float2 uv);
}  // namespace caustics::shader
#endif

CAUSTICS_SHARED_BEGIN
// instance: the hit's instance index (GLSL gl_InstanceCustomIndexEXT, HLSL InstanceID()); primitive:
// its triangle; barycentrics: the hit attribute (b1, b2), weights (1 - b1 - b2, b1, b2).
CAUSTICS_FN SurfaceHit sceneSurfaceHit(uint instance, uint primitive, float2 barycentrics) {
    GpuInstance inst = sceneInstance(instance);
    uint base = inst.firstIndex + 3u * primitive;
    uint i0 = inst.firstVertex + sceneIndex(base);
    uint i1 = inst.firstVertex + sceneIndex(base + 1u);
    uint i2 = inst.firstVertex + sceneIndex(base + 2u);
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

#endif  // CAUSTICS_COMMON_SCENE_SURFACE_H
