#version 460
#extension GL_GOOGLE_include_directive : require
// G-buffer vertex stage: pulls the vertex of index-buffer slot gl_VertexIndex of this instance from
// the GPU scene buffers and transforms it to world and clip space.
#include "gbuffer_io.glsl"

layout(location = 0) out vec3 outWorldPos;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec2 outUv;

void main() {
    GpuInstance inst = sceneInstances[draw.instanceIndex];
    uint vertex = inst.firstVertex + sceneIndices[inst.firstIndex + uint(gl_VertexIndex)];
    vec4 world = inst.objectToWorld * vec4(scenePosition(vertex), 1.0);
    GpuVertex v = sceneVertices[vertex];
    outWorldPos = world.xyz;
    outNormal = mat3(inst.normalToWorld) * v.normal;
    outUv = vec2(v.u, v.v);
    gl_Position = camera.viewProj * world;
}
