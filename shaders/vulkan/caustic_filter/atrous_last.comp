#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// The last a-trous iteration: pool to caustics.radiance (atrous_body.glsl).
#define kAtrousLast 1
#include "caustic_filter/atrous_body.glsl"
