// Caustic visibility map raster (paper 3.2, Figure 3; mirror of shaders/vulkan/caustic_maps/
// caustic_map.vert): vertex pulling, one draw per instance with firstInstance = the scene instance.
// SV_InstanceID does not include firstInstance, so the backend's draw parameters (b0, space998) add it.
#define SCENE_NO_TEXTURES
#define SCENE_NO_TLAS
#include "scene/scene.hlsli"
#include "scene/camera.hlsli"
#include "caustic_maps/caustic_map.hlsli"

ByteAddressBuffer maps : register(t0, space1);
struct Push { uint mapIndex; };
ConstantBuffer<Push> pc : register(b0, space999);
struct DrawParameters { uint baseVertex; uint firstInstance; };
ConstantBuffer<DrawParameters> drawParams : register(b0, space998);

struct CausticMapVaryings {
    float4 position : SV_Position;
    nointerpolation uint instance : TEXCOORD0;
};

CausticMapVaryings main(uint vertexIndex : SV_VertexID, uint instanceId : SV_InstanceID) {
    uint instance = instanceId + drawParams.firstInstance;
    GpuInstance inst = sceneInstance(instance);
    uint v = inst.firstVertex + sceneIndex(inst.firstIndex + vertexIndex);
    float4 world = mat4Mul(inst.objectToWorld, float4(scenePosition(v), 1.0f));
    CausticMapVaryings o;
    o.instance = instance;
    o.position = vulkanToD3DClip(mat4Mul(loadCausticMap(maps, pc.mapIndex).viewProj, world));
    return o;
}
