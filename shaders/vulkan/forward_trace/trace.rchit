#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_ray_tracing : require
// Closest hit for every caustic trace: returns the surface (instance, primitive, barycentrics, t);
// the raygen shader does the shading, so recursion depth stays 1 (paper Figure 4a, iterative).
#include "forward_trace/caustic_hit.glsl"
layout(location = 0) rayPayloadInEXT TracePayload payload;
hitAttributeEXT vec2 attribs;
void main() {
    payload.barycentrics = attribs;
    payload.instance = gl_InstanceCustomIndexEXT;
    payload.primitive = gl_PrimitiveID;
    payload.t = gl_HitTEXT;
}
