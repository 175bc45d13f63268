#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#extension GL_EXT_control_flow_attributes : require
// Vulkan entry of caustics.temporal for the second type in list order (common/specular_list.h;
// docs/caustics.md "Second-type memory"): temporal.comp with FILTER_LIST_ORDER.
#define FILTER_LIST_ORDER 1
#include "scene/camera.glsl"
#include "temporal.h"
layout(local_size_x = 8, local_size_y = 8) in;
void main() { temporalThread(gl_WorkGroupID.x, gl_LocalInvocationID.xy); }
