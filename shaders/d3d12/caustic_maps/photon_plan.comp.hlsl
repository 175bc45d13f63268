// caustics.photonPlan (mirror of shaders/vulkan/caustic_maps/photon_plan.comp): each layer's photons
// per emitting texel, its launch range in the forward grid, and that grid.
#include "caustic_maps/layer_plan.hlsli"

// CausticMapGpu::photons: byte 164 of each 176-byte map (caustic_map.hlsli's layout).
float layerPhotons(ByteAddressBuffer maps, uint layer) { return asfloat(maps.Load(176u * layer + 164u)); }

ByteAddressBuffer maps : register(t0, space0);
RWByteAddressBuffer plans : register(u1, space0);
RWByteAddressBuffer args : register(u2, space0);
struct Push { uint layers; float raysPerTexel; };
ConstantBuffer<Push> pc : register(b0, space999);

[numthreads(1, 1, 1)]
void main() {
    // A layer without emitting texels gives its share to the others in proportion (photon_plan.comp).
    float planned = 0.0f, live = 0.0f;
    for (uint j = 0u; j < pc.layers; ++j) {
        planned += layerPhotons(maps, j);
        if (plans.Load(layerPlanAddress(j, kLayerPlanEmitters)) > 0u) live += layerPhotons(maps, j);
    }
    float scale = live > 0.0f ? planned / live : 0.0f;
    uint offset = 0u;
    for (uint k = 0u; k < pc.layers; ++k) {
        uint e = plans.Load(layerPlanAddress(k, kLayerPlanEmitters));
        float photons = layerPhotons(maps, k) * scale;
        float r = layerPhotons(maps, k) > 0.0f ? (e > 0u ? photons / float(e) : 0.0f) : pc.raysPerTexel;
        uint s = uint(ceil(r));
        plans.Store(layerPlanAddress(k, kLayerPlanRaysPerTexel), asuint(r));
        plans.Store(layerPlanAddress(k, kLayerPlanSamplesPerTexel), s);
        plans.Store(layerPlanAddress(k, kLayerPlanLaunchOffset), offset);
        plans.Store(layerPlanAddress(k, kLayerPlanLaunches), e * s);
        offset += e * s;
    }
    args.Store3(0u, uint3(offset, 1u, 1u));
}
