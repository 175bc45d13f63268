// Second-type gather (paper 3.3, Figure 6; mirror of shaders/vulkan/backward_trace/gather.rgen): a
// tiny ray at each stored forward hit; the any-hit shader accumulates it into every sphere containing it.
#include "forward_trace/caustic_hit.hlsli"
#include "caustic_maps/emitter_list.hlsli"
#include "backward_trace/gather_payload.hlsli"
RaytracingAccelerationStructure sphereTlas : register(t0, space0);
ByteAddressBuffer hits : register(t2, space0);
RWByteAddressBuffer stats : register(u3, space0);
struct Push { uint maxStoredHits; };
ConstantBuffer<Push> pc : register(b0, space999);

[shader("raygeneration")]
void main() {
    uint i = DispatchRaysIndex().x;
    if (i == 0u) stats.InterlockedAdd(4u * kStatGatherLaunches, DispatchRaysDimensions().x);
    if (i >= min(stats.Load(4u * kStatStoredHitAttempts), pc.maxStoredHits)) return;
    GatherPayload payload;
    payload.hitIndex = i;
    RayDesc ray;
    ray.Origin = loadCausticHit(hits, i).position;
    ray.TMin = 0.0f;
    ray.Direction = float3(0.0f, 0.0f, 1.0f);
    ray.TMax = 1.0e-6f;
    TraceRay(sphereTlas, RAY_FLAG_NONE, 0xFF, 0, 0, 0, ray, payload);
}
