// G-buffer pixel stage (mirror of shaders/vulkan/gbuffer/gbuffer.frag): the six targets of
// passes/include/caustics/gbuffer.h.
#include "gbuffer/gbuffer_io.hlsli"

struct GBufferTargets {
    float4 normalRoughness : SV_Target0;
    float4 albedoMetallic : SV_Target1;
    float4 optics : SV_Target2;
    float linearDepth : SV_Target3;
    uint objectId : SV_Target4;
};

GBufferTargets main(GBufferVaryings i) {
    CameraConstants camera = cameraBlock.camera;
    GpuInstance inst = sceneInstance(draw.instanceIndex);
    GpuMaterial m = sceneMaterial(inst.material);
    float3 toEye = camera.eye.xyz - i.worldPos;
    float3 n = i.normal;
    if (dot(n, n) < 1e-12f) n = cross(ddx(i.worldPos), ddy(i.worldPos));
    n = normalize(n);
    if (dot(n, toEye) < 0.0f) n = -n;
    GBufferTargets o;
    o.normalRoughness = float4(n, m.roughness);
    o.albedoMetallic = float4(sceneBaseColor(m, i.uv), m.metallic);
    o.optics = sceneOpticsEncoding(m);
    o.linearDepth = dot(i.worldPos - camera.eye.xyz, camera.forward.xyz);
    o.objectId = draw.instanceIndex + 1u;
    return o;
}
