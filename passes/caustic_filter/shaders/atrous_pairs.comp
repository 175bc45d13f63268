#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#extension GL_EXT_control_flow_attributes : require
// Vulkan entry of caustics.atrous.N.pairs (12 packed pair weights per pixel); the body is atrous.h (docs/shaders.md).
#define kAtrousPairs 1
#include "atrous.h"
layout(local_size_x = 64) in;
void main() { atrousThread(gl_WorkGroupID.x, gl_LocalInvocationIndex); }
