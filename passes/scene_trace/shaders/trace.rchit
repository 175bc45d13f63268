#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_ray_tracing : require
// Closest hit of every scene trace (forward.h traceScene): reports the surface (instance, primitive,
// barycentrics, t); the ray-generation shader does the shading, so recursion depth stays 1 (paper
// Figure 4a, iterative). The backward pass traces with it too.
#include "common/caustic_hit.h"
layout(location = 0) rayPayloadInEXT TracePayload payload;
hitAttributeEXT vec2 attribs;
void main() {
    payload.barycentrics = attribs;
    payload.instance = gl_InstanceCustomIndexEXT;
    payload.primitive = gl_PrimitiveID;
    payload.t = gl_HitTEXT;
}
