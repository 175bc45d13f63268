// D3D12 entries of caustics.maps; the body is caustic_map.h (docs/shaders.md).
struct CausticMapVaryings {
    float4 position : SV_Position;
    nointerpolation uint instance : TEXCOORD0;
};
#if defined(CAUSTICS_STAGE_VERT)
#define SCENE_NO_TEXTURES
#define SCENE_NO_TLAS
#include "common/scene_resources.h"
#include "scene/camera.hlsli"
#include "caustic_map.h"
// SV_InstanceID does not include firstInstance, so the backend's draw parameters (b0, space998) add it.
struct DrawParameters { uint baseVertex; uint firstInstance; };
ConstantBuffer<DrawParameters> drawParams : register(b0, space998);

CausticMapVaryings main(uint vertexIndex : SV_VertexID, uint instanceId : SV_InstanceID) {
    CausticMapVaryings o;
    o.instance = instanceId + drawParams.firstInstance;
    o.position = vulkanToD3DClip(causticMapVertex(o.instance, vertexIndex));
    return o;
}
#elif defined(CAUSTICS_STAGE_FRAG)
#define CAUSTIC_MAP_FRAGMENT
#include "caustic_map.h"
uint main(CausticMapVaryings i) : SV_Target0 { return causticMapObjectId(i.instance); }
#endif
