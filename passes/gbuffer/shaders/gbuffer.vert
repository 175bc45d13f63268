#version 460
#extension GL_GOOGLE_include_directive : require
// Vulkan vertex entry of gbuffer; the body is gbuffer.h (docs/shaders.md).
#define SCENE_UNIFORM_TEXTURE_INDEX
#define SCENE_NO_TLAS
#include "common/scene_resources.h"
#include "gbuffer.h"
layout(location = 0) out vec3 outWorldPos;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec2 outUv;
void main() {
    GBufferVaryings o = gbufferVertex(uint(gl_VertexIndex), gl_Position);
    outWorldPos = o.worldPos;
    outNormal = o.normal;
    outUv = o.uv;
}
