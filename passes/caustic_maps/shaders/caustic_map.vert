#version 460
#extension GL_GOOGLE_include_directive : require
// Vulkan vertex entry of caustics.maps; the body is caustic_map.h (docs/shaders.md).
#define SCENE_NO_TEXTURES
#define SCENE_NO_TLAS
#include "common/scene_resources.h"
#include "caustic_map.h"
layout(location = 0) flat out uint outInstance;
void main() {
    outInstance = uint(gl_InstanceIndex);   // the scene instance: the draw's firstInstance
    gl_Position = causticMapVertex(uint(gl_InstanceIndex), uint(gl_VertexIndex));
}
