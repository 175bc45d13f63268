#version 460
#extension GL_EXT_samplerless_texture_functions : require
#extension GL_GOOGLE_include_directive : require
// Vulkan entry of the object-id remap pass; the body is remap_object_ids.h (docs/shaders.md).
#include "remap_object_ids.h"
layout(local_size_x = 8, local_size_y = 8) in;
void main() { remapObjectIdsThread(gl_GlobalInvocationID.xy); }
