#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Vulkan entry of caustics.filterOutput for the second type in list order (common/specular_list.h;
// docs/caustics.md "Second-type memory"): output.comp with FILTER_LIST_ORDER.
#define FILTER_LIST_ORDER 1
#include "output.h"
layout(local_size_x = 8, local_size_y = 8) in;
void main() { filterOutputThread(gl_WorkGroupID.x, gl_LocalInvocationID.xy); }
