#version 460
#extension GL_GOOGLE_include_directive : require
// Vulkan vertex entry of caustics_output; the body is caustics_output.h (docs/shaders.md).
#include "caustics_output.h"
void main() { gl_Position = fullScreenTriangleVertex(uint(gl_VertexIndex)); }
