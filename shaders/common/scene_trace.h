#ifndef CAUSTICS_COMMON_SCENE_TRACE_H
#define CAUSTICS_COMMON_SCENE_TRACE_H
// The ray-tracing intrinsics a ray-generation body uses, behind one spelling (docs/shaders.md):
// traceScene(origin, tMin, dir, tMax) traces the scene TLAS (scene shim) opaque with hit group 0 and
// miss 0 (forward_trace/trace.rchit, trace.rmiss) and returns their TracePayload (t < 0: miss).
// GLSL and HLSL only: C++ type-checks the pure functions of a body, which take and return values.
#include "common/caustic_hit.h"

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

#endif  // CAUSTICS_COMMON_SCENE_TRACE_H
