#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Vulkan entry of caustics.atrous.N.select; the body is atrous_select.h (docs/shaders.md).
#include "atrous_select.h"
layout(local_size_x = 64) in;
void main() { atrousSelectThread(gl_GlobalInvocationID.x); }
