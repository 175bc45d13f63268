#ifndef CAUSTICS_COMMON_CAUSTIC_STATS_H
#define CAUSTICS_COMMON_CAUSTIC_STATS_H
// The slots of the caustic passes' statistics buffer (uint32 each), named once in the shared dialect
// for the shaders and C++ (passes/internal/caustics/caustic_passes.h uses these; docs/shaders.md).
// Slot kStatRaysPerLight + l counts the forward rays launched for scene light l (skipped lights: 0).
#include "common/lang.h"

CAUSTICS_SHARED_BEGIN
CAUSTICS_CONST uint kMaxCausticLights = 60u;        // lights with a counter slot (caustics::kMaxCausticLights)
CAUSTICS_CONST uint kStatStoredHitAttempts = 0u;    // diffuse hits offered to the hit buffer
CAUSTICS_CONST uint kStatSplats = 1u;               // first-type splats that passed the depth test
CAUSTICS_CONST uint kStatGatherHits = 2u;           // (hit, sphere) pairs accumulated
CAUSTICS_CONST uint kStatSpheres = 3u;              // backward hits that became spheres
CAUSTICS_CONST uint kStatRaysPerLight = 4u;
// Cost counters (docs/caustics.md, "Cost that follows the caustic work"): forward ray segments traced
// (traceRay calls, not paths), map texels that emit (specular 3x3 neighbourhood), map texels the
// forward dispatch covers (texels x samples), and launches of the gather dispatch.
CAUSTICS_CONST uint kStatForwardSegments = kStatRaysPerLight + kMaxCausticLights;
CAUSTICS_CONST uint kStatEmitterTexels = kStatForwardSegments + 1u;
CAUSTICS_CONST uint kStatDispatchedTexels = kStatForwardSegments + 2u;
CAUSTICS_CONST uint kStatGatherLaunches = kStatForwardSegments + 3u;
// Radiance contributions the HLSL float compare-and-swap loop gave up on after its bounded attempts
// (docs/d3d12.md). Always 0 on Vulkan.
CAUSTICS_CONST uint kStatAccumulationGiveUps = kStatForwardSegments + 4u;
// Second-type cost (docs/caustics.md, "Second-type cost"): specular camera pixels (the backward pass's
// launches when dispatched indirectly), launches of the backward dispatch, spheres that found no slot
// below the sphere capacity (kStatSpheres counts them too), and that capacity (AABB slots built).
CAUSTICS_CONST uint kStatSpecularPixels = kStatForwardSegments + 5u;
CAUSTICS_CONST uint kStatBackwardLaunches = kStatForwardSegments + 6u;
CAUSTICS_CONST uint kStatSpheresDropped = kStatForwardSegments + 7u;
CAUSTICS_CONST uint kStatSphereCapacity = kStatForwardSegments + 8u;
// Fixed-point accumulation (docs/caustics.md, "Fixed point"): adds that pinned a radiance word at its
// maximum (causticStatsWarnings names the exposure), and the frame's scale (float bits, written by
// caustics.setup: the fixed-point word is value x this). Always 0 on the float path.
CAUSTICS_CONST uint kStatSaturatedAdds = kStatForwardSegments + 9u;
CAUSTICS_CONST uint kStatFixedPointScale = kStatForwardSegments + 10u;
CAUSTICS_CONST uint kStatCount = kStatFixedPointScale + 1u;
CAUSTICS_SHARED_END

#endif  // CAUSTICS_COMMON_CAUSTIC_STATS_H
