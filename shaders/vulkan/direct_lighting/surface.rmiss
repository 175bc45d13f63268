#version 460
#extension GL_EXT_ray_tracing : require
#extension GL_GOOGLE_include_directive : require
#include "payloads.glsl"
layout(location = 0) rayPayloadInEXT SurfacePayload payload;
void main() { payload.instance = ~0u; }
