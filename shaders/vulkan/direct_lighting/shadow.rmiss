#version 460
#extension GL_EXT_ray_tracing : require
// Shadow rays skip closest-hit shaders; only a miss (nothing between the point and the light) runs.
layout(location = 1) rayPayloadInEXT uint unoccluded;
void main() { unoccluded = 1u; }
