#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Vulkan entry of caustics.specularPixels; the body is specular_pixels.h (docs/shaders.md).
#include "specular_pixels.h"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
void main() { specularPixelsThread(gl_GlobalInvocationID.xy, gl_WorkGroupID.xy, gl_LocalInvocationIndex); }
