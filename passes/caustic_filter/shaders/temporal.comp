#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#extension GL_EXT_control_flow_attributes : require
// Vulkan entry of caustics.temporal; the body is temporal.h (docs/shaders.md).
#include "scene/camera.glsl"
#include "temporal.h"
layout(local_size_x = 8, local_size_y = 8) in;
void main() { temporalThread(gl_WorkGroupID.x, gl_LocalInvocationID.xy); }
