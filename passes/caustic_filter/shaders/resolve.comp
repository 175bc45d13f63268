#version 460
#extension GL_GOOGLE_include_directive : require
// Vulkan entry of caustics.resolve; the body is resolve.h (docs/shaders.md).
#include "resolve.h"
layout(local_size_x = 8, local_size_y = 8) in;
void main() { resolveThread(gl_GlobalInvocationID.xy); }
