#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Vulkan entry of caustics.emitters; the body is emitters.h (docs/shaders.md).
#define SCENE_NO_TEXTURES
#define SCENE_NO_TLAS
#include "common/scene_resources.h"
#include "emitters.h"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
void main() { emittersThread(gl_GlobalInvocationID); }
