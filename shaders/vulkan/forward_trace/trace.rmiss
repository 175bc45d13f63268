#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_ray_tracing : require
#include "forward_trace/caustic_hit.glsl"
layout(location = 0) rayPayloadInEXT TracePayload payload;
void main() { payload.t = -1.0; }
