#ifndef CAUSTICS_PASS_GATHER_H
#define CAUSTICS_PASS_GATHER_H
// caustics.gather in the shared dialect (paper 3.3, Figure 6; docs/shaders.md): a ray of length 1e-6 at
// each stored forward hit through the sphere TLAS. The intersection shader reports the hit when the ray
// origin lies in a sphere's gather disk (common/gather_disk.h, the expression the CPU brute-force test
// uses); the any-hit shader adds the density estimate into the sphere's pixel and ignores the hit, so
// traversal visits every containing sphere (the geometry is NO_DUPLICATE_ANY_HIT).
// Entries: gather.rgen, gather.rmiss, sphere.rint, gather.rahit / gather_fixed.rahit /
// gather_fixed64.rahit (float, 32-bit and 64-bit fixed-point radiance atomics; docs/caustics.md
// "Fixed point"), gather*.hlsl.
#include "common/caustic_hit.h"
#include "common/gather_disk.h"

CAUSTICS_SHARED_BEGIN
// Push constants (gather_bindings.h), 12 bytes.
struct GatherParams {
    uint maxStoredHits;   // records the hit buffer holds
    uint width;           // the image's, pixels
    // 1: radianceWords hold the second type in list order, 3 words per entry of caustics.specularPixels'
    // list (common/specular_list.h); 0: 3 words per pixel.
    uint listOrder;
};
// The trace's payload (DXR payloads are structs): the stored hit the ray starts at.
struct GatherPayload {
    uint hitIndex;
};
CAUSTICS_CONST float kGatherRayLength = 1.0e-6f;

// Whether the stored hit h counts for sphere s: the same object, on the same side of the surface.
CAUSTICS_FN bool gatherAccepts(CausticSphere s, CausticHit h) {
    return h.objectId == s.objectId && dot(h.normal, s.normal) > 0.0f;
}
// Its radiance in the sphere's pixel: L = transmittance x flux f_r(wi, wo) / (pi r^2) (docs/physics.md).
CAUSTICS_FN float3 gatherRadiance(CausticSphere s, CausticHit h) {
    return causticHitReflectedFlux(h, s.outgoing) * s.transmittance / (kPi * s.radius * s.radius);
}
CAUSTICS_SHARED_END

#if !defined(CAUSTICS_LANG_CPP)
// The generated resources, one declaration per radiance word type (gather_bindings.h).
#if defined(CAUSTICS_FIXED_POINT_64)
#include "bindings/gather_fixed64.h"
#elif defined(CAUSTICS_FIXED_POINT)
#include "bindings/gather_fixed.h"
#else
#include "bindings/gather.h"
#endif

// Ray generation: whether launch i has a stored hit to gather (launches past the stored count idle;
// without indirect dispatch the grid is the buffer's capacity), counting the launches once.
bool gatherLaunchHasHit(uint i, uint launchCount) {
    if (i == 0u) statsAtomicAdd(kStatGatherLaunches, launchCount);
    return i < min(statsLoad(kStatStoredHitAttempts), params.maxStoredHits);
}

// Intersection: sphere slot `primitive` holds the ray origin in its gather disk. Slots no sphere was
// written to hold a point box at the origin (lavapipe's builder does not take NaN boxes as inactive)
// and are refused by index (docs/caustics.md, "Memory").
bool gatherSphereContains(uint primitive, float3 origin) {
    if (primitive >= min(statsLoad(kStatSpheres), statsLoad(kStatSphereCapacity))) return false;
    CausticSphere s = spheresLoad(primitive);
    return insideGatherDisk(origin, s.centre, s.normal, s.radius);
}

// Any-hit: the stored hit's radiance added into sphere `primitive`'s pixel.
#if defined(CAUSTICS_STAGE_RAHIT)
#include "common/radiance_atomics.h"
#include "common/resources.h"
#include "common/specular_list.h"
void gatherAnyHit(uint primitive, uint hitIndex) {
    CausticSphere s = spheresLoad(primitive);
    CausticHit h = unpackCausticHit(hitsLoad(hitIndex));
    if (!gatherAccepts(s, h)) return;
    // A sphere's pixel is always listed (the backward pass launched from its entry).
    int2 p = int2(int(s.pixel % params.width), int(s.pixel / params.width));
    uint target = params.listOrder != 0u ? specularListEntry(CAUSTICS_TEXEL(specularIndex, int2(p.x >> 3, p.y >> 3)), p) : s.pixel;
    addRadiance(target, gatherRadiance(s, h));
    statsAtomicAdd(kStatGatherHits, 1u);
}
#endif  // CAUSTICS_STAGE_RAHIT
#endif  // !CAUSTICS_LANG_CPP
#endif  // CAUSTICS_PASS_GATHER_H
