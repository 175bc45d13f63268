#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_ray_tracing : require
// Shadow rays skip closest-hit shaders; only a miss (nothing between the point and the light) runs.
#include "direct_light.h"
layout(location = 1) rayPayloadInEXT ShadowPayload payload;
void main() { payload.unoccluded = 1u; }
