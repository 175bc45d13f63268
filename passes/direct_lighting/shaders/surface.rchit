#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_ray_tracing : require
// Closest hit of direct_lighting's surface rays: which triangle, where (direct_light.h).
#include "direct_light.h"
layout(location = 0) rayPayloadInEXT SurfacePayload payload;
hitAttributeEXT vec2 barycentrics;
void main() {
    payload.instance = uint(gl_InstanceCustomIndexEXT);
    payload.primitive = uint(gl_PrimitiveID);
    payload.barycentrics = barycentrics;
}
