#version 460
#extension GL_EXT_samplerless_texture_functions : require
#extension GL_GOOGLE_include_directive : require
// Vulkan entry of the second-type guide fill pass; the body is second_type_guide_fill.h (docs/shaders.md).
#include "second_type_guide_fill.h"
layout(local_size_x = 8, local_size_y = 8) in;
void main() { secondTypeGuideFillThread(gl_GlobalInvocationID.xy); }
