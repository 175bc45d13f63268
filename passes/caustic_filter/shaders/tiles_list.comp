#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Vulkan entry of caustics.filterTiles for the second type in list order (common/specular_list.h;
// docs/caustics.md "Second-type memory"): tiles.comp with FILTER_LIST_ORDER.
#define FILTER_LIST_ORDER 1
#include "scene/camera.glsl"
#include "tiles_thread.h"
layout(local_size_x = 8, local_size_y = 8) in;
void main() { filterTilesThread(gl_WorkGroupID.xy, gl_GlobalInvocationID.xy, gl_LocalInvocationIndex); }
