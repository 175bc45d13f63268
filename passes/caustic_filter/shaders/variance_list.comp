#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Vulkan entry of caustics.variance for the second type in list order (common/specular_list.h;
// docs/caustics.md "Second-type memory"): variance.comp with FILTER_LIST_ORDER.
#define FILTER_LIST_ORDER 1
#include "variance.h"
layout(local_size_x = 8, local_size_y = 8) in;
void main() { varianceThread(gl_WorkGroupID.x, gl_LocalInvocationID.xy); }
