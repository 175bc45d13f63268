#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// An a-trous iteration before the last: pool to pool (atrous_body.glsl).
#include "caustic_filter/atrous_body.glsl"
