#version 460
#extension GL_EXT_samplerless_texture_functions : require
#extension GL_GOOGLE_include_directive : require
// Vulkan entry of the filter's combine pass; the body is combine_types.h (docs/shaders.md).
#include "combine_types.h"
layout(local_size_x = 8, local_size_y = 8) in;
void main() { combineTypesThread(gl_GlobalInvocationID.xy); }
