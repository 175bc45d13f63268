#version 460
#extension GL_EXT_samplerless_texture_functions : require
#extension GL_GOOGLE_include_directive : require
// Vulkan fragment entry of caustics_output; the body is caustics_output.h (docs/shaders.md).
#define CAUSTICS_STAGE_FRAG 1
#include "caustics_output.h"
layout(location = 0) out vec4 outColor;
void main() { outColor = causticsOutputFragment(gl_FragCoord); }
