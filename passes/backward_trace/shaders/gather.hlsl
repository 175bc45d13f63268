// D3D12 entries of caustics.gather (gather.rgen, gather.rmiss, and the any-hit with float radiance, or the
// fixed-point one where gather_fixed*.hlsl define the word first); the body is gather.h (docs/shaders.md).
#include "gather.h"
#if defined(CAUSTICS_STAGE_RGEN)
[shader("raygeneration")]
void main() {
    uint i = DispatchRaysIndex().x;
    if (!gatherLaunchHasHit(i, DispatchRaysDimensions().x)) return;
    GatherPayload payload;
    payload.hitIndex = i;
    RayDesc ray;
    ray.Origin = hitsLoad(i).position;
    ray.TMin = 0.0f;
    ray.Direction = float3(0.0f, 0.0f, 1.0f);
    ray.TMax = kGatherRayLength;
    TraceRay(sphereTlas, RAY_FLAG_NONE, 0xFF, 0, 0, 0, ray, payload);
}
#elif defined(CAUSTICS_STAGE_RMISS)
[shader("miss")]
void main(inout GatherPayload payload) {}
#elif defined(CAUSTICS_STAGE_RAHIT)
struct SphereAttributes { float2 unused; };   // sphere.hlsl's, 8 bytes
// The hit is ignored so traversal visits every sphere that contains the ray origin.
[shader("anyhit")]
void main(inout GatherPayload payload, in SphereAttributes attribs) {
    gatherAnyHit(PrimitiveIndex(), payload.hitIndex);
    IgnoreHit();
}
#endif
