#version 460
#extension GL_GOOGLE_include_directive : require
// Caustic visibility map raster (paper 3.2, Figure 3): vertex pulling from the scene buffers, one
// draw per instance (gl_InstanceIndex = scene instance index via firstInstance).
#define SCENE_NO_TEXTURES
#define SCENE_NO_TLAS
#include "scene/scene.glsl"
#include "caustic_maps/caustic_map.glsl"

layout(set = 1, binding = 0, std430) readonly buffer Maps { CausticMap maps[]; };
layout(push_constant) uniform Push { uint mapIndex; } pc;

layout(location = 0) flat out uint outInstance;

void main() {
    uint instance = uint(gl_InstanceIndex);
    GpuInstance inst = sceneInstances[instance];
    uint v = inst.firstVertex + sceneIndices[inst.firstIndex + uint(gl_VertexIndex)];
    vec4 world = inst.objectToWorld * vec4(scenePosition(v), 1.0);
    outInstance = instance;
    gl_Position = maps[pc.mapIndex].viewProj * world;
}
