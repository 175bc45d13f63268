#ifndef CAUSTICS_D3D12_SCENE_HLSLI
#define CAUSTICS_D3D12_SCENE_HLSLI
// D3D12 declarations of the GPU scene, the same binding layout as shaders/vulkan/scene/scene.glsl:
// register space 0 by default (define SCENE_SPACE before including to move it), registers = the GLSL
// binding numbers. The structs and the surface of a hit are the shared dialect's common/scene.h and
// common/scene.h (docs/shaders.md, "Scene API"). Storage buffers are ByteAddressBuffers read
// with the templated Load<T> (the D3D12 backend creates raw views for every storage buffer,
// docs/d3d12.md); a float4x4 is read column by column (common/lang.h).
// Define SCENE_NO_TEXTURES / SCENE_UNIFORM_TEXTURE_INDEX / SCENE_NO_TLAS as for the GLSL.
#include "common/scene.h"

#ifndef SCENE_SPACE
#define SCENE_SPACE space0
#endif
#define SCENE_MAX_TEXTURES 256

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

// The accessors common/scene.h reads the scene through (the Vulkan shim has the same).
uint sceneIndex(uint i) { return sceneIndexBuffer.Load(4u * i); }
float3 scenePosition(uint vertex) { return loadFloat3(scenePositionBuffer, 12u * vertex); }
GpuVertex sceneVertex(uint i) { return sceneVertexBuffer.Load<GpuVertex>(48u * i); }
GpuMaterial sceneMaterial(uint i) { return sceneMaterialBuffer.Load<GpuMaterial>(96u * i); }
GpuInstance sceneInstance(uint i) {
    uint o = 160u * i;
    GpuInstance inst;
    inst.objectToWorld = loadFloat4x4(sceneInstanceBuffer, o);
    inst.normalToWorld = loadFloat4x4(sceneInstanceBuffer, o + 64u);
    uint4 a = sceneInstanceBuffer.Load4(o + 128u);
    uint4 b = sceneInstanceBuffer.Load4(o + 144u);
    inst.material = a.x; inst.firstVertex = a.y; inst.firstIndex = a.z; inst.triangleCount = a.w;
    inst.objectId = b.x; inst.mesh = b.y; inst.flags = b.z; inst.pad = b.w;
    return inst;
}
uint sceneLightCount() { return sceneLightBuffer.Load(0); }
GpuLight sceneLight(uint i) { return sceneLightBuffer.Load<GpuLight>(16u + 64u * i); }   // after the 16-byte header

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

#endif
