#version 460
#extension GL_EXT_ray_tracing : require
#extension GL_GOOGLE_include_directive : require
#include "payloads.glsl"
layout(location = 0) rayPayloadInEXT SurfacePayload payload;
hitAttributeEXT vec2 barycentrics;
void main() {
    payload.instance = uint(gl_InstanceCustomIndexEXT);
    payload.primitive = uint(gl_PrimitiveID);
    payload.barycentrics = barycentrics;
}
