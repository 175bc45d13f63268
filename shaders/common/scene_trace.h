#ifndef CAUSTICS_COMMON_SCENE_TRACE_H
#define CAUSTICS_COMMON_SCENE_TRACE_H
// The scene trace every ray-generation shader of the forward and backward passes shares (GLSL and HLSL
// only; the includer declares sceneTlas and TracePayload, common/caustic_hit.h).
// traceScene(origin, tMin, dir, tMax): the scene TLAS traced opaque with hit group 0 and miss 0
// (trace.rchit, trace.rmiss), their TracePayload returned (t < 0: miss).
#include "common/lang.h"
#if defined(CAUSTICS_LANG_GLSL)
layout(location = 0) rayPayloadEXT TracePayload scenePayload;
TracePayload traceScene(float3 origin, float tMin, float3 dir, float tMax) {
    scenePayload.t = -1.0f;
    traceRayEXT(sceneTlas, gl_RayFlagsOpaqueEXT, 0xFF, 0, 0, 0, origin, tMin, dir, tMax, 0);
    return scenePayload;
}
#elif defined(CAUSTICS_LANG_HLSL)
TracePayload traceScene(float3 origin, float tMin, float3 dir, float tMax) {
    TracePayload payload;
    payload.barycentrics = (float2)0.0f;
    payload.instance = 0u;
    payload.primitive = 0u;
    payload.t = -1.0f;
    RayDesc ray;
    ray.Origin = origin;
    ray.TMin = tMin;
    ray.Direction = dir;
    ray.TMax = tMax;
    TraceRay(sceneTlas, RAY_FLAG_FORCE_OPAQUE, 0xFF, 0, 0, 0, ray, payload);
    return payload;
}
#endif
#endif
