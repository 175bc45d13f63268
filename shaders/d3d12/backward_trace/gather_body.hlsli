// Any-hit of the gather (mirror of shaders/vulkan/backward_trace/gather_body.glsl): density estimate
// L = transmittance x sum(flux f_r(wi, wo)) / (pi r^2) for the sphere's pixel, only for hits on the same
// object and side; the hit is ignored so traversal visits every containing sphere.
#include "common/lang.h"
#include "forward_trace/caustic_hit.hlsli"
#include "backward_trace/gather_payload.hlsli"
ByteAddressBuffer spheres : register(t1, space0);
ByteAddressBuffer hits : register(t2, space0);
RWByteAddressBuffer stats : register(u3, space0);
#define RADIANCE_REGISTER u4
#define RADIANCE_SPACE space0
#include "forward_trace/radiance_atomics.h"

[shader("anyhit")]
void main(inout GatherPayload payload, in SphereAttributes attribs) {
    CausticSphere s = loadCausticSphere(spheres, PrimitiveIndex());
    CausticHit h = loadCausticHit(hits, payload.hitIndex);
    if (h.objectId == s.objectId && dot(h.normal, s.normal) > 0.0f) {
        addRadiance(s.pixel, causticHitReflectedFlux(h, s.outgoing) * s.transmittance / (kPi * s.radius * s.radius));
        stats.InterlockedAdd(4u * kStatGatherHits, 1u);
    }
    IgnoreHit();
}
