#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#extension GL_EXT_control_flow_attributes : require
// Vulkan entry of the last caustics.atrous.N for the second type in list order (common/specular_list.h;
// docs/caustics.md "Second-type memory"): atrous_last.comp with FILTER_LIST_ORDER.
#define FILTER_LIST_ORDER 1
#define kAtrousLast 1
#include "atrous.h"
layout(local_size_x = 64) in;
void main() { atrousThread(gl_WorkGroupID.x, gl_LocalInvocationIndex); }
