#version 460
#extension GL_GOOGLE_include_directive : require
// Vulkan entry of caustics.filterTiles.list; the body is tiles.h (docs/shaders.md).
#include "tile_list_thread.h"
layout(local_size_x = 8, local_size_y = 8) in;
void main() { tileListThread(gl_GlobalInvocationID.xy); }
