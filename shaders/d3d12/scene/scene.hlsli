#ifndef CAUSTICS_D3D12_SCENE_HLSLI
#define CAUSTICS_D3D12_SCENE_HLSLI
// HLSL side of the GPU scene, mirror of shaders/vulkan/scene/scene.glsl: one binding layout, by
// default register space 0 (define SCENE_SPACE before including to move it), registers = the GLSL
// binding numbers. Storage buffers are ByteAddressBuffers read at the std430 offsets of the GLSL
// structs: the D3D12 backend creates raw views for every storage buffer (docs/d3d12.md), so one
// declaration fits any buffer whatever its structStride.
//   t0 sceneTlas, t1 positions, t2 vertices, t3 indices, t4 materials, t5 instances, t6 lights,
//   s7 sceneSampler, t8.. sceneTextures[SCENE_MAX_TEXTURES]
// Define SCENE_NO_TEXTURES / SCENE_UNIFORM_TEXTURE_INDEX / SCENE_NO_TLAS as for the GLSL.
#include "common/lang.h"
#include "common/fresnel.h"
#include "common/specular_event.h"

#ifndef SCENE_SPACE
#define SCENE_SPACE space0
#endif
#define SCENE_MAX_TEXTURES 256

static const uint kMaterialSpecular = 1u;
static const uint kMaterialTransmissive = 2u;
static const uint kMaterialMetallic = 4u;
static const uint kMaterialDoubleSided = 8u;
static const uint kMaterialThinWalled = 16u;
static const uint kInstanceSpecular = 1u;
static const uint kMaskDiffuse = 0x1u;
static const uint kMaskSpecular = 0x2u;
static const uint kLightPoint = 0u;
static const uint kLightSpot = 1u;
static const uint kLightDirectional = 2u;

struct GpuMaterial {   // std430, 96 bytes
    float3 baseColor;        float metallic;
    float3 specularColor;    float roughness;
    float3 attenuationColor; float attenuationDistance;
    float3 emissive;         float ior;
    float transmission; float specular; float thickness; int baseColorTexture;
    uint flags;
};

// Column-major 4x4 as glm and GLSL store it: mat4MulPoint(m, v) is GLSL's m * v.
struct Mat4 { float4 c0, c1, c2, c3; };
float4 mat4Mul(Mat4 m, float4 v) { return m.c0 * v.x + m.c1 * v.y + m.c2 * v.z + m.c3 * v.w; }
float3 mat3Mul(Mat4 m, float3 v) { return m.c0.xyz * v.x + m.c1.xyz * v.y + m.c2.xyz * v.z; }   // mat3(m) * v

struct GpuInstance {   // std430, 160 bytes
    Mat4 objectToWorld;
    Mat4 normalToWorld;
    uint material; uint firstVertex; uint firstIndex; uint triangleCount;
    uint objectId; uint mesh; uint flags;
};

struct GpuVertex { float3 normal; float u; float4 tangent; float v; };   // std430, 48 bytes

struct GpuLight {   // 64 bytes
    float3 position;  uint type;
    float3 direction; float range;
    float3 intensity; float cosInner;
    float cosOuter; uint castsCaustics;
};

#ifndef SCENE_NO_TLAS   // raster/compute shaders (vs/ps/cs_6_0) have no DXR types; as in scene.glsl
RaytracingAccelerationStructure sceneTlas : register(t0, SCENE_SPACE);
#endif
ByteAddressBuffer scenePositionBuffer : register(t1, SCENE_SPACE);
ByteAddressBuffer sceneVertexBuffer : register(t2, SCENE_SPACE);
ByteAddressBuffer sceneIndexBuffer : register(t3, SCENE_SPACE);
ByteAddressBuffer sceneMaterialBuffer : register(t4, SCENE_SPACE);
ByteAddressBuffer sceneInstanceBuffer : register(t5, SCENE_SPACE);
ByteAddressBuffer sceneLightBuffer : register(t6, SCENE_SPACE);
#ifndef SCENE_NO_TEXTURES
SamplerState sceneSampler : register(s7, SCENE_SPACE);
Texture2D<float4> sceneTextures[SCENE_MAX_TEXTURES] : register(t8, SCENE_SPACE);
#endif

float3 loadFloat3(ByteAddressBuffer b, uint offset) { return asfloat(b.Load3(offset)); }
float4 loadFloat4(ByteAddressBuffer b, uint offset) { return asfloat(b.Load4(offset)); }
Mat4 loadMat4(ByteAddressBuffer b, uint offset) {
    Mat4 m;
    m.c0 = loadFloat4(b, offset);
    m.c1 = loadFloat4(b, offset + 16u);
    m.c2 = loadFloat4(b, offset + 32u);
    m.c3 = loadFloat4(b, offset + 48u);
    return m;
}

uint sceneIndex(uint i) { return sceneIndexBuffer.Load(4u * i); }
float3 scenePosition(uint vertex) { return loadFloat3(scenePositionBuffer, 12u * vertex); }

GpuVertex sceneVertex(uint i) {
    uint o = 48u * i;
    GpuVertex v;
    float4 a = loadFloat4(sceneVertexBuffer, o);
    v.normal = a.xyz;
    v.u = a.w;
    v.tangent = loadFloat4(sceneVertexBuffer, o + 16u);
    v.v = asfloat(sceneVertexBuffer.Load(o + 32u));
    return v;
}

GpuMaterial sceneMaterial(uint i) {
    uint o = 96u * i;
    GpuMaterial m;
    float4 a = loadFloat4(sceneMaterialBuffer, o), b = loadFloat4(sceneMaterialBuffer, o + 16u);
    float4 c = loadFloat4(sceneMaterialBuffer, o + 32u), d = loadFloat4(sceneMaterialBuffer, o + 48u);
    uint4 e = sceneMaterialBuffer.Load4(o + 64u);
    m.baseColor = a.xyz; m.metallic = a.w;
    m.specularColor = b.xyz; m.roughness = b.w;
    m.attenuationColor = c.xyz; m.attenuationDistance = c.w;
    m.emissive = d.xyz; m.ior = d.w;
    m.transmission = asfloat(e.x); m.specular = asfloat(e.y); m.thickness = asfloat(e.z);
    m.baseColorTexture = asint(e.w);
    m.flags = sceneMaterialBuffer.Load(o + 80u);
    return m;
}

GpuInstance sceneInstance(uint i) {
    uint o = 160u * i;
    GpuInstance inst;
    inst.objectToWorld = loadMat4(sceneInstanceBuffer, o);
    inst.normalToWorld = loadMat4(sceneInstanceBuffer, o + 64u);
    uint4 a = sceneInstanceBuffer.Load4(o + 128u);
    uint4 b = sceneInstanceBuffer.Load4(o + 144u);
    inst.material = a.x; inst.firstVertex = a.y; inst.firstIndex = a.z; inst.triangleCount = a.w;
    inst.objectId = b.x; inst.mesh = b.y; inst.flags = b.z;
    return inst;
}

uint sceneLightCount() { return sceneLightBuffer.Load(0); }
GpuLight sceneLight(uint i) {
    uint o = 16u + 64u * i;   // after the 16-byte header
    GpuLight l;
    float4 a = loadFloat4(sceneLightBuffer, o), b = loadFloat4(sceneLightBuffer, o + 16u);
    float4 c = loadFloat4(sceneLightBuffer, o + 32u);
    uint2 d = sceneLightBuffer.Load2(o + 48u);
    l.position = a.xyz; l.type = asuint(a.w);
    l.direction = b.xyz; l.range = b.w;
    l.intensity = c.xyz; l.cosInner = c.w;
    l.cosOuter = asfloat(d.x); l.castsCaustics = d.y;
    return l;
}

float3 sceneBaseColor(GpuMaterial m, float2 uv) {
    float3 c = m.baseColor;
#ifndef SCENE_NO_TEXTURES
    if (m.baseColorTexture >= 0) {
#ifdef SCENE_UNIFORM_TEXTURE_INDEX
        c *= sceneTextures[m.baseColorTexture].SampleLevel(sceneSampler, uv, 0.0f).rgb;
#else
        c *= sceneTextures[NonUniformResourceIndex(m.baseColorTexture)].SampleLevel(sceneSampler, uv, 0.0f).rgb;
#endif
    }
#endif
    return c;
}

struct SurfaceHit {
    float3 position;
    float3 geometricNormal;
    float3 shadingNormal;
    float2 uv;
    float3 baseColor;
    uint instance;
    uint objectId;
    GpuMaterial material;
    OpticalMaterial optics;
};

// instance: InstanceID() (== instance index); primitive: PrimitiveIndex(); barycentrics: the hit
// attribute (b1, b2), weights (1 - b1 - b2, b1, b2).
SurfaceHit sceneSurfaceHit(uint instance, uint primitive, float2 barycentrics) {
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
    h.position = mat4Mul(inst.objectToWorld, float4(pObject, 1.0f)).xyz;
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

bool sceneMaterialIsSpecular(GpuMaterial m) { return (m.flags & kMaterialSpecular) != 0u; }

float4 sceneOpticsEncoding(GpuMaterial m) {
    float reflectance = m.metallic + (1.0f - m.metallic) * m.specular * dielectricF0(m.ior);
    float transmittance = (1.0f - m.metallic) * m.transmission;
    return float4(reflectance, transmittance, m.ior, sceneMaterialIsSpecular(m) ? 1.0f : 0.0f);
}

#endif
