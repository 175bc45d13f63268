#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_ray_tracing : require
#extension GL_EXT_samplerless_texture_functions : require
// Vulkan miss of caustics.gather (nothing to do: the any-hit shader gathered); the body is gather.h.
#include "gather.h"
layout(location = 0) rayPayloadInEXT GatherPayload payload;
void main() {}
