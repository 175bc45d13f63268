#version 460
#extension GL_EXT_samplerless_texture_functions : require
#extension GL_GOOGLE_include_directive : require
// Vulkan entry of the filter's combine pass for the second type in list order (common/specular_list.h;
// docs/caustics.md "Second-type memory"): combine_types.comp with FILTER_LIST_ORDER.
#define FILTER_LIST_ORDER 1
#include "combine_types.h"
layout(local_size_x = 8, local_size_y = 8) in;
void main() { combineTypesThread(gl_GlobalInvocationID.xy); }
