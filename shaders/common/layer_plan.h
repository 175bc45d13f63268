#ifndef CAUSTICS_COMMON_LAYER_PLAN_H
#define CAUSTICS_COMMON_LAYER_PLAN_H
// One caustic map layer's share of this frame's photons (docs/caustics.md, "Photon budget"), 32 bytes
// std430, in the shared dialect: written by caustics.emitters and caustics.photonPlan, read by the
// forward trace. C++: caustics::CausticLayerPlanGpu (passes/include/caustics/caustic_layer_plan.h),
// checked member for member in passes/caustic_maps/photon_plan_pass.cpp.
#include "common/lang.h"

CAUSTICS_SHARED_BEGIN
struct CausticLayerPlan {
    uint emitters;          // emitting texels, counted by caustics.emitters
    float raysPerTexel;     // photons per emitting texel (the layer's budget / emitters, or the setting)
    uint samplesPerTexel;   // ceil(raysPerTexel): launches per emitting texel
    uint launchOffset;      // the layer's first launch in caustics.forward's grid
    uint launches;          // emitters x samplesPerTexel
    uint emitted;           // launches that emitted a photon
    uint pad0;
    uint pad1;
};
CAUSTICS_SHARED_END

#endif  // CAUSTICS_COMMON_LAYER_PLAN_H
