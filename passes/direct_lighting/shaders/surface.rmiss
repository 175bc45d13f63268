#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_ray_tracing : require
// Miss of direct_lighting's surface rays (direct_light.h).
#include "direct_light.h"
layout(location = 0) rayPayloadInEXT SurfacePayload payload;
void main() { payload.instance = ~0u; }
