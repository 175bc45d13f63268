// D3D12 entries of gbuffer; the body is gbuffer.h (docs/shaders.md).
#define SCENE_UNIFORM_TEXTURE_INDEX
#define SCENE_NO_TLAS
#include "common/scene_resources.h"
#include "scene/camera.hlsli"
#include "gbuffer.h"

struct GBufferStageVaryings {
    float4 position : SV_Position;
    float3 worldPos : TEXCOORD0;
    float3 normal : TEXCOORD1;
    float2 uv : TEXCOORD2;
};

#if defined(CAUSTICS_STAGE_VERT)
// Non-indexed draw: SV_VertexID includes firstVertex like gl_VertexIndex.
GBufferStageVaryings main(uint vertexIndex : SV_VertexID) {
    float4 clip;
    GBufferVaryings v = gbufferVertex(vertexIndex, clip);
    GBufferStageVaryings o;
    o.position = vulkanToD3DClip(clip);
    o.worldPos = v.worldPos;
    o.normal = v.normal;
    o.uv = v.uv;
    return o;
}
#elif defined(CAUSTICS_STAGE_FRAG)
struct GBufferStageTargets {
    float4 normalRoughness : SV_Target0;
    float4 albedoMetallic : SV_Target1;
    float4 optics : SV_Target2;
    float linearDepth : SV_Target3;
    uint objectId : SV_Target4;
};

GBufferStageTargets main(GBufferStageVaryings s) {
    GBufferVaryings i;
    i.worldPos = s.worldPos;
    i.normal = s.normal;
    i.uv = s.uv;
    GBufferTargets t = gbufferFragment(i);
    GBufferStageTargets o;
    o.normalRoughness = t.normalRoughness;
    o.albedoMetallic = t.albedoMetallic;
    o.optics = t.optics;
    o.linearDepth = t.linearDepth;
    o.objectId = t.objectId;
    return o;
}
#endif
