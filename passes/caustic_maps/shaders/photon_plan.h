#ifndef CAUSTICS_PASS_PHOTON_PLAN_H
#define CAUSTICS_PASS_PHOTON_PLAN_H
// caustics.photonPlan in the shared dialect (docs/shaders.md): each layer's photons per emitting texel
// from the emitter counts of caustics.emitters, the launch ranges of the forward pass's one-dimensional
// grid, and that grid (docs/caustics.md, "Photon budget"). A layer with a budget N and E emitting
// texels emits N / E photons per texel (fractional: the last sample of a texel is emitted with the
// remainder's probability); each photon carries its texel's flux over N / E, so the layer's energy does
// not depend on N. Without a budget every texel emits raysPerTexel photons (the paper's emission).
// Entries: photon_plan.comp, photon_plan.hlsl.
#include "common/layer_plan.h"

CAUSTICS_SHARED_BEGIN
// Push constants (photon_plan_bindings.h), 8 bytes.
struct PhotonPlanParams {
    uint layers;
    float raysPerTexel;   // CausticsSettings::raysPerTexel, for layers without a budget
};
// The maps are read as 32-bit words: caustics::CausticMapGpu is 44 words, its `photons` word 41
// (static_assert in photon_plan_pass.cpp).
CAUSTICS_CONST uint kCausticMapWords = 44u;
CAUSTICS_CONST uint kCausticMapPhotonsWord = 41u;
CAUSTICS_SHARED_END

#if defined(CAUSTICS_LANG_CPP)
namespace caustics::shader {
// The pass's buffers: defined by the C++ caller (tests).
float mapWordsLoad(uint i);
CausticLayerPlan plansLoad(uint i);
void plansStore(uint i, CausticLayerPlan plan);
void argsStore(uint i, uint v);
}  // namespace caustics::shader
#else
#include "bindings/photon_plan.h"   // generated from passes/caustic_maps/photon_plan_bindings.h
#endif

CAUSTICS_SHARED_BEGIN
CAUSTICS_FN float layerPhotons(uint layer) { return mapWordsLoad(kCausticMapWords * layer + kCausticMapPhotonsWord); }

CAUSTICS_FN void planPhotons(PhotonPlanParams pc) {
    // A layer whose map lists no emitting texel (its objects hidden from the light after all) gives its
    // share to the others in proportion: the budget is spent whole, and the split stays a weighting.
    float planned = 0.0f, live = 0.0f;
    for (uint j = 0u; j < pc.layers; ++j) {
        planned += layerPhotons(j);
        if (plansLoad(j).emitters > 0u) live += layerPhotons(j);
    }
    float scale = live > 0.0f ? planned / live : 0.0f;
    uint offset = 0u;
    for (uint k = 0u; k < pc.layers; ++k) {
        CausticLayerPlan plan = plansLoad(k);
        uint e = plan.emitters;
        float photons = layerPhotons(k) * scale;
        float r = layerPhotons(k) > 0.0f ? (e > 0u ? photons / float(e) : 0.0f) : pc.raysPerTexel;
        uint s = uint(ceil(r));
        plan.raysPerTexel = r;
        plan.samplesPerTexel = s;
        plan.launchOffset = offset;
        plan.launches = e * s;
        plansStore(k, plan);
        offset += e * s;
    }
    argsStore(0u, offset);
    argsStore(1u, 1u);
    argsStore(2u, 1u);
}
CAUSTICS_SHARED_END

#endif  // CAUSTICS_PASS_PHOTON_PLAN_H
