#version 460
#extension GL_EXT_samplerless_texture_functions : require
#extension GL_GOOGLE_include_directive : require
// Vulkan entry of the composite pass; the body is composite.h (docs/shaders.md).
#include "composite.h"
layout(local_size_x = 8, local_size_y = 8) in;
void main() { compositeThread(gl_GlobalInvocationID.xy); }
