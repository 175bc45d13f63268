#ifndef CAUSTICS_LAYER_PLAN_GLSL
#define CAUSTICS_LAYER_PLAN_GLSL
// std430 mirror of caustics::CausticLayerPlanGpu (passes/include/caustics/caustic_layer_plan.h), 32 bytes:
// one caustic map layer's share of this frame's photons (docs/caustics.md, "Photon budget").
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
#endif
