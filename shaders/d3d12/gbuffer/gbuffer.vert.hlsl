// G-buffer vertex stage (mirror of shaders/vulkan/gbuffer/gbuffer.vert): pulls vertex SV_VertexID
// of this instance from the scene buffers. Non-indexed draw: SV_VertexID includes firstVertex like
// gl_VertexIndex.
#include "gbuffer/gbuffer_io.hlsli"

GBufferVaryings main(uint vertexIndex : SV_VertexID) {
    GpuInstance inst = sceneInstance(draw.instanceIndex);
    uint vertex = inst.firstVertex + sceneIndex(inst.firstIndex + vertexIndex);
    float4 world = mat4Mul(inst.objectToWorld, float4(scenePosition(vertex), 1.0f));
    GpuVertex v = sceneVertex(vertex);
    GBufferVaryings o;
    o.worldPos = world.xyz;
    o.normal = mat3Mul(inst.normalToWorld, v.normal);
    o.uv = float2(v.u, v.v);
    o.position = vulkanToD3DClip(mul(cameraBlock.camera.viewProj, world));
    return o;
}
