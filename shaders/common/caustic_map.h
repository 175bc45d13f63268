#ifndef CAUSTICS_COMMON_CAUSTIC_MAP_H
#define CAUSTICS_COMMON_CAUSTIC_MAP_H
// One caustic map layer as the map, emitter and forward shaders read it, in the shared dialect:
// caustics::CausticMapGpu (passes/internal/caustics/caustic_map_plan.h), 176 bytes std430; and the
// emitter list of caustics.emitters (docs/caustics.md, "Cost"): one uint per map texel that emits,
// x | y << 13 | layer << 26 (map side <= 8192, <= 64 layers; caustic_emitters_pass.cpp checks both).
#include "common/lang.h"

CAUSTICS_SHARED_BEGIN
struct CausticMap {
    float3 origin;    uint light;
    float3 right;     float extent;         // perspective: tan(half-angle); orthographic: half-extent
    float3 up;        uint orthographic;
    float3 forward;   float nearPlane;
    float3 intensity; float cosInner;
    float3 spotAxis;  float cosOuter;       // cosOuter <= -1: no cone
    float4x4 viewProj;
    float range;                            // KHR_lights_punctual range, 0 = infinite
    float photons;                          // this layer's photons per frame; 0: raysPerTexel per texel
    uint cluster;                           // the layer's number among its light's layers
    uint ownerRow;                          // row of the instance -> layer ownership table
};

// Does layer m own the scene instance whose ownership entry is `owner` (its cluster holds it)? The
// owners table has a row of instanceCount entries per light: cluster + 1 of the owning layer, 0 for
// none (caustic_map_plan.h); the entry is owners[m.ownerRow * instanceCount + instance].
CAUSTICS_FN bool causticLayerOwnsEntry(CausticMap m, uint owner) { return owner == m.cluster + 1u; }

CAUSTICS_FN uint packEmitter(uint2 texel, uint layer) { return texel.x | (texel.y << 13) | (layer << 26); }
CAUSTICS_FN uint2 emitterTexel(uint packed) { return uint2(packed & 0x1FFFu, (packed >> 13) & 0x1FFFu); }
CAUSTICS_FN uint emitterLayer(uint packed) { return packed >> 26; }
CAUSTICS_SHARED_END

#endif  // CAUSTICS_COMMON_CAUSTIC_MAP_H
