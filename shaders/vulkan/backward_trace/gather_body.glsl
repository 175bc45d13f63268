// Any-hit of the gather: density estimate L = transmittance x sum(flux f_r(wi, wo)) / (pi r^2) for the
// sphere's pixel, only for hits on the same object and the same side of the surface. The hit is
// ignored so traversal visits every containing sphere (geometry is NO_DUPLICATE_ANY_HIT).
#extension GL_EXT_ray_tracing : require
#include "common/lang.h"
#include "forward_trace/caustic_hit.glsl"
layout(set = 0, binding = 1, std430) readonly buffer Spheres { CausticSphere spheres[]; };
layout(set = 0, binding = 2, std430) readonly buffer Hits { CausticHitRecord hits[]; };
layout(set = 0, binding = 3, std430) buffer Stats { uint stats[]; };
#define RADIANCE_SET 0
#define RADIANCE_BINDING 4
#include "forward_trace/radiance_atomics.h"
layout(location = 0) rayPayloadInEXT uint hitIndex;
void main() {
    CausticSphere s = spheres[gl_PrimitiveID];
    CausticHit h = unpackCausticHit(hits[hitIndex]);
    if (h.objectId == s.objectId && dot(h.normal, s.normal) > 0.0) {
        addRadiance(s.pixel, causticHitReflectedFlux(h, s.outgoing) * s.transmittance / (kPi * s.radius * s.radius));
        atomicAdd(stats[kStatGatherHits], 1u);
    }
    ignoreIntersectionEXT;
}
