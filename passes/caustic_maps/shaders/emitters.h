#ifndef CAUSTICS_PASS_EMITTERS_H
#define CAUSTICS_PASS_EMITTERS_H
// caustics.emitters in the shared dialect (docs/shaders.md): the map texels that emit photons,
// compacted into a list, counted per layer for caustics.photonPlan. The paper (3.2) emits only where
// the map sees a specular surface; testing that here instead of in every forward launch makes the
// forward dispatch, and so its cost, follow the specular texels instead of the whole map
// (docs/caustics.md, "Cost"). A texel emits when its 3x3 neighbourhood sees a specular surface (the
// ray finds the exact sub-texel hit; the neighbourhood keeps silhouette texels whose centre misses the
// object) and, for spot lights, when it is not entirely outside the cone (photons there carry zero
// flux: spotAttenuation is 0). Of a light with several layers, a layer lists only texels that see an
// instance it owns (its cluster's), each layer into its own segment of the list (layer x mapSize^2).
// Entries: emitters.comp, emitters.hlsl.
#include "common/caustic_map.h"
#include "common/caustic_stats.h"
#include "common/emission.h"
#include "common/layer_plan.h"
#include "common/scene.h"

CAUSTICS_SHARED_BEGIN
// Push constants (emitters_bindings.h), 8 bytes.
struct EmittersParams {
    uint mapSize;
    uint instanceCount;   // row length of the owners table
};

// Conservative: the texel's centre direction is farther from the spot axis than the outer cone
// angle plus the texel's angular radius (half-diagonal over the distance to the z = 1 plane point).
CAUSTICS_FN bool texelOutsideSpotCone(CausticMap m, uint2 t, float n) {
    if (m.orthographic != 0u || m.cosOuter <= -1.0f) return false;
    float2 q = perspectiveMapPlanePoint(float2(t) + 0.5f, n, m.extent);
    float3 d = m.forward + q.x * m.right + q.y * m.up;
    float distance = length(d);
    float angularRadius = 1.41421356f * m.extent / n / distance;
    float angle = acos(clamp(dot(d / distance, m.spotAxis), -1.0f, 1.0f));
    return angle > acos(clamp(m.cosOuter, -1.0f, 1.0f)) + angularRadius;
}
CAUSTICS_SHARED_END

#if !defined(CAUSTICS_LANG_CPP)
#include "bindings/emitters.h"   // generated from passes/caustic_maps/emitters_bindings.h
#include "common/resources.h"
#if defined(CAUSTICS_LANG_GLSL)
#define EMITTERS_COUNT_TEXEL(layer) atomicAdd(plans[layer].emitters, 1u)
#else
#define EMITTERS_COUNT_TEXEL(layer) emittersCountTexel(layer)
uint emittersCountTexel(uint layer) {
    uint slot;
    plans.InterlockedAdd(32u * layer, 1u, slot);   // CausticLayerPlan::emitters
    return slot;
}
#endif

bool texelIsSpecular(int2 t, int layer, CausticMap m) {
    int n = int(params.mapSize) - 1;
    uint id = CAUSTICS_TEXEL_ARRAY_UINT(mapObjectIds, clamp(t, int2(0, 0), int2(n, n)), layer);
    if (id == 0u || id > params.instanceCount) return false;
    return sceneMaterialIsSpecular(sceneMaterial(sceneInstance(id - 1u).material)) &&
           causticLayerOwnsEntry(m, ownersLoad(m.ownerRow * params.instanceCount + id - 1u));
}

void emittersThread(uint3 id) {
    if (id.x >= params.mapSize || id.y >= params.mapSize) return;
    int layer = int(id.z);
    CausticMap m = mapsLoad(uint(layer));
    bool specular = false;
    for (int dy = -1; dy <= 1 && !specular; ++dy)
        for (int dx = -1; dx <= 1 && !specular; ++dx) specular = texelIsSpecular(int2(id.xy) + int2(dx, dy), layer, m);
    if (!specular || texelOutsideSpotCone(m, id.xy, float(params.mapSize))) return;
    uint slot = EMITTERS_COUNT_TEXEL(uint(layer));
    emittersStore(uint(layer) * params.mapSize * params.mapSize + slot, packEmitter(id.xy, uint(layer)));
    statsAtomicAdd(kStatEmitterTexels, 1u);
}
#endif  // !CAUSTICS_LANG_CPP

#endif  // CAUSTICS_PASS_EMITTERS_H
