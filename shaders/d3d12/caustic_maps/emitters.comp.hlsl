// caustics.emitters (mirror of shaders/vulkan/caustic_maps/emitters.comp): the map texels that emit,
// compacted into a list, and the forward pass's indirect grid (list length x samples per texel).
#define SCENE_NO_TEXTURES
#define SCENE_NO_TLAS
#include "scene/scene.hlsli"
#include "common/emission.h"
#include "caustic_maps/caustic_map.hlsli"
#include "caustic_maps/emitter_list.hlsli"
#include "caustic_maps/layer_plan.hlsli"

ByteAddressBuffer maps : register(t0, space1);
Texture2DArray<uint> mapObjectIds : register(t1, space1);
RWByteAddressBuffer emitters : register(u2, space1);
RWByteAddressBuffer plans : register(u3, space1);
RWByteAddressBuffer stats : register(u4, space1);
ByteAddressBuffer owners : register(t5, space1);
struct Push { uint mapSize; uint instanceCount; };
ConstantBuffer<Push> pc : register(b0, space999);

bool texelIsSpecular(int2 t, int layer, CausticMap m) {
    int n = int(pc.mapSize) - 1;
    uint id = mapObjectIds.Load(int4(clamp(t, int2(0, 0), int2(n, n)), layer, 0));
    if (id == 0u || id > pc.instanceCount) return false;
    return sceneMaterialIsSpecular(sceneMaterial(sceneInstance(id - 1u).material)) &&
           causticLayerOwns(owners, m, pc.instanceCount, id - 1u);
}

bool texelOutsideSpotCone(CausticMap m, uint2 t) {
    if (m.orthographic != 0u || m.cosOuter <= -1.0f) return false;
    float n = float(pc.mapSize);
    float2 q = perspectiveMapPlanePoint(float2(t) + 0.5f, n, m.extent);
    float3 d = m.forward + q.x * m.right + q.y * m.up;
    float distance = length(d);
    float angularRadius = 1.41421356f * m.extent / n / distance;
    float angle = acos(clamp(dot(d / distance, m.spotAxis), -1.0f, 1.0f));
    return angle > acos(clamp(m.cosOuter, -1.0f, 1.0f)) + angularRadius;
}

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    if (id.x >= pc.mapSize || id.y >= pc.mapSize) return;
    int layer = int(id.z);
    CausticMap m = loadCausticMap(maps, uint(layer));
    bool specular = false;
    for (int dy = -1; dy <= 1 && !specular; ++dy)
        for (int dx = -1; dx <= 1 && !specular; ++dx) specular = texelIsSpecular(int2(id.xy) + int2(dx, dy), layer, m);
    if (!specular || texelOutsideSpotCone(m, id.xy)) return;
    uint slot;
    plans.InterlockedAdd(layerPlanAddress(uint(layer), kLayerPlanEmitters), 1u, slot);
    emitters.Store(4u * (uint(layer) * pc.mapSize * pc.mapSize + slot), packEmitter(id.xy, uint(layer)));
    stats.InterlockedAdd(4u * kStatEmitterTexels, 1u);
}
