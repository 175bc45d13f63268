#version 460
#extension GL_GOOGLE_include_directive : require
// Vulkan entry of the grid-from-count pass; the body is grid_from_count.h (docs/shaders.md).
#include "grid_from_count.h"
layout(local_size_x = 1) in;
void main() { writeGridFromCount(params); }
