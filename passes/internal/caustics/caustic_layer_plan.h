#pragma once
// One caustic map layer's share of a frame's photons, as caustics.photonPlan writes it on the GPU
// (docs/caustics.md, "Photon budget"; CausticOutputs::layerPlans, one per CausticMapPlan::maps entry).
#include <cstdint>

namespace caustics {

// std430, as the shaders see it: shaders/common/layer_plan.h (32 bytes).
struct CausticLayerPlanGpu {
    uint32_t emitters = 0;          // emitting texels, counted by caustics.emitters
    float raysPerTexel = 0.0f;      // photons per emitting texel: CausticMapGpu::photons / emitters, or the setting
    uint32_t samplesPerTexel = 0;   // ceil(raysPerTexel): forward launches per emitting texel
    uint32_t launchOffset = 0;      // the layer's first launch in caustics.forward's grid
    uint32_t launches = 0;          // emitters x samplesPerTexel
    uint32_t emitted = 0;           // launches that emitted a photon
    uint32_t pad0 = 0, pad1 = 0;
};
static_assert(sizeof(CausticLayerPlanGpu) == 32);

}  // namespace caustics
