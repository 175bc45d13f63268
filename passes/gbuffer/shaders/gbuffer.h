#ifndef CAUSTICS_PASS_GBUFFER_H
#define CAUSTICS_PASS_GBUFFER_H
// gbuffer in the shared dialect (docs/shaders.md): one draw per instance (the instance index in a
// push constant), the vertices pulled from the scene buffers (no vertex input state), and the six
// targets of passes/include/caustics/gbuffer.h. Entries: gbuffer.vert / .frag, gbuffer.hlsl (the
// fragment entries define CAUSTICS_STAGE_FRAG, as the HLSL embedder does).
#include "common/camera.h"
#include "common/scene.h"

CAUSTICS_SHARED_BEGIN
// Push constants (gbuffer_bindings.h), 4 bytes.
struct GBufferParams {
    uint instanceIndex;   // the scene instance drawn
};

// What the vertex stage hands the fragment stage (besides the clip position).
struct GBufferVaryings {
    float3 worldPos;
    float3 normal;   // world, not normalised
    float2 uv;
};

// The G-buffer's targets of one pixel.
struct GBufferTargets {
    float4 normalRoughness;   // xyz unit normal facing the viewer, w roughness
    float4 albedoMetallic;    // rgb linear base colour, a metallic
    float4 optics;            // sceneOpticsEncoding
    float linearDepth;        // along the optical axis
    uint objectId;            // instance index + 1 (0: background)
};

// Shading normal turned towards the viewer: the G-buffer holds the side that is seen, whatever the
// winding (double-sided and thin-walled surfaces are seen from both sides). `n` is the interpolated
// normal, already replaced by the facet normal where it was degenerate.
CAUSTICS_FN float3 gbufferFacingNormal(float3 n, float3 toEye) {
    float3 u = normalize(n);
    return dot(u, toEye) < 0.0f ? -u : u;
}
CAUSTICS_SHARED_END

#if !defined(CAUSTICS_LANG_CPP)
#include "bindings/gbuffer.h"   // generated from passes/gbuffer/gbuffer_bindings.h
#if defined(CAUSTICS_LANG_GLSL)
#define GBUFFER_DDX(v) dFdx(v)
#define GBUFFER_DDY(v) dFdy(v)
#else
#define GBUFFER_DDX(v) ddx(v)
#define GBUFFER_DDY(v) ddy(v)
#endif

// Vertex `vertexIndex` (of the draw) of the drawn instance: its varyings, and its clip position
// (Vulkan clip) in `clip`.
GBufferVaryings gbufferVertex(uint vertexIndex, CAUSTICS_OUT(float4) clip) {
    GpuInstance inst = sceneInstance(draw.instanceIndex);
    uint vertex = inst.firstVertex + sceneIndex(inst.firstIndex + vertexIndex);
    float4 world = mat4Mul(inst.objectToWorld, float4(scenePosition(vertex), 1.0f));
    GpuVertex v = sceneVertex(vertex);
    GBufferVaryings o;
    o.worldPos = toFloat3(world);
    o.normal = mat3Mul(inst.normalToWorld, v.normal);
    o.uv = float2(v.u, v.v);
    clip = mat4Mul(camera.viewProj, world);
    return o;
}

#if defined(CAUSTICS_STAGE_FRAG)   // screen-space derivatives: fragment stage only
GBufferTargets gbufferFragment(GBufferVaryings i) {
    GpuInstance inst = sceneInstance(draw.instanceIndex);
    GpuMaterial m = sceneMaterial(inst.material);
    float3 toEye = toFloat3(camera.eye) - i.worldPos;
    float3 n = i.normal;
    // A degenerate interpolated normal falls back to the facet normal from screen-space derivatives.
    if (dot(n, n) < 1e-12f) n = cross(GBUFFER_DDX(i.worldPos), GBUFFER_DDY(i.worldPos));
    GBufferTargets o;
    o.normalRoughness = float4(gbufferFacingNormal(n, toEye), m.roughness);
    o.albedoMetallic = float4(sceneBaseColor(m, i.uv), m.metallic);
    o.optics = sceneOpticsEncoding(m);
    o.linearDepth = dot(i.worldPos - toFloat3(camera.eye), toFloat3(camera.forward));
    o.objectId = draw.instanceIndex + 1u;
    return o;
}
#endif  // CAUSTICS_STAGE_FRAG
#endif  // !CAUSTICS_LANG_CPP

#endif  // CAUSTICS_PASS_GBUFFER_H
