#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Vulkan entry of the second-type guide pass; the body is second_type_guides.h (docs/shaders.md).
#include "second_type_guides.h"
layout(local_size_x = 8, local_size_y = 8) in;
void main() { secondTypeGuidesThread(gl_GlobalInvocationID.xy); }
