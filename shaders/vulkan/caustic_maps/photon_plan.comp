#version 460
#extension GL_GOOGLE_include_directive : require
// caustics.photonPlan: each layer's photons per emitting texel from the emitter counts of
// caustics.emitters, the launch ranges of the forward pass's one-dimensional grid, and that grid
// (docs/caustics.md, "Photon budget"). A layer with a budget N and E emitting texels emits N / E
// photons per texel (fractional: the last sample of a texel is emitted with the remainder's
// probability); each photon carries its texel's flux over N / E, so the layer's energy does not depend
// on N. Without a budget every texel emits raysPerTexel photons (the paper's emission).
#include "caustic_maps/caustic_map.glsl"
#include "caustic_maps/layer_plan.glsl"

layout(local_size_x = 1) in;

layout(set = 0, binding = 0, std430) readonly buffer Maps { CausticMap maps[]; };
layout(set = 0, binding = 1, std430) buffer Plans { CausticLayerPlan plans[]; };
layout(set = 0, binding = 2, std430) writeonly buffer Args { uint args[]; };   // forward grid (x, 1, 1)
layout(push_constant) uniform Push { uint layers; float raysPerTexel; } pc;

void main() {
    // A layer whose map lists no emitting texel (its objects hidden from the light after all) gives its
    // share to the others in proportion: the budget is spent whole, and the split stays a weighting.
    float planned = 0.0, live = 0.0;
    for (uint k = 0u; k < pc.layers; ++k) {
        planned += maps[k].photons;
        if (plans[k].emitters > 0u) live += maps[k].photons;
    }
    float scale = live > 0.0 ? planned / live : 0.0;
    uint offset = 0u;
    for (uint k = 0u; k < pc.layers; ++k) {
        uint e = plans[k].emitters;
        float photons = maps[k].photons * scale;
        float r = maps[k].photons > 0.0 ? (e > 0u ? photons / float(e) : 0.0) : pc.raysPerTexel;
        uint s = uint(ceil(r));
        plans[k].raysPerTexel = r;
        plans[k].samplesPerTexel = s;
        plans[k].launchOffset = offset;
        plans[k].launches = e * s;
        offset += e * s;
    }
    args[0] = offset;
    args[1] = 1u;
    args[2] = 1u;
}
