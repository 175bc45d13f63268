#ifndef CAUSTICS_GBUFFER_IO_GLSL
#define CAUSTICS_GBUFFER_IO_GLSL
// Shared declarations of the G-buffer raster shaders: scene set 0, camera set 1, one draw per
// instance with the instance index in a push constant (vertex pulling, no vertex input state).
#define SCENE_UNIFORM_TEXTURE_INDEX
#define SCENE_NO_TLAS
#include "scene/scene.glsl"
#include "scene/camera.glsl"

layout(set = 1, binding = 0, std140) uniform CameraBlock { CameraConstants camera; };
layout(push_constant) uniform DrawConstants { uint instanceIndex; } draw;

#endif
