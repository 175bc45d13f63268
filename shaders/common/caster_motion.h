#ifndef CAUSTICS_COMMON_CASTER_MOTION_H
#define CAUSTICS_COMMON_CASTER_MOTION_H
// Caster motion (docs/caustics.md "Moving casters"), shared by caustics.forward, which accumulates it
// per pixel, and caustics.temporal, which reprojects the caustic history with it; the C++ tests call
// the same functions.
#include "common/lang.h"

CAUSTICS_SHARED_BEGIN
// The per-pixel words hold displacement sums in units of 1 / kCasterMotionScale m (signed, two's
// complement in a uint) and, in the fourth word, the photon count. A photon's displacement is clamped to
// kCasterMotionMaxShift m: 2^31 / (4096 x 4) = 131072 photons may land in one pixel in one frame before
// a sum wraps; a caster that jumps further than that per frame keeps no useful history anyway.
CAUSTICS_CONST float kCasterMotionScale = 4096.0f;
CAUSTICS_CONST float kCasterMotionMaxShift = 4.0f;
CAUSTICS_CONST uint kCasterMotionWords = 4u;
// Per instance, the 3 rows of the 3x4 matrix prev x inverse(current) (this frame's pose to last frame's).
CAUSTICS_CONST uint kCasterMotionRowsPerInstance = 3u;

// Where world point x on an instance was last frame, from the instance's three rows r0..r2.
CAUSTICS_FN float3 instanceRowsApply(float4 r0, float4 r1, float4 r2, float3 x) {
    float4 p = float4(x, 1.0f);
    return float3(dot(r0, p), dot(r1, p), dot(r2, p));
}

// Where a photon that reached receiver point r along `dir` would have landed last frame, minus r, when
// the specular chain that sent it moved by `chainShift` since then (last frame's position of its last
// moving vertex minus this frame's) and sent it in the same direction: last frame's photon left from
// v + shift along dir and met the receiver's tangent plane (normal n) at r + shift - dir (shift . n) /
// (dir . n). Exact for a caster translating under a distant light onto a planar receiver; a point light
// (the chain's image moves by more than the chain), a rotation that turns the exit direction, or a
// curved receiver make it a first-order estimate. Zero at grazing incidence.
CAUSTICS_FN float3 casterMotionReceiverShift(float3 chainShift, float3 dir, float3 n) {
    float cosIn = dot(dir, n);
    if (abs(cosIn) < 1e-3f) return float3(0.0f, 0.0f, 0.0f);
    return chainShift - dir * (dot(chainShift, n) / cosIn);
}

// A shift as the three words added per photon (fixed point, clamped).
CAUSTICS_FN int3 casterMotionFixed(float3 shift) {
    float3 c = clamp(shift, splat3(-kCasterMotionMaxShift), splat3(kCasterMotionMaxShift));
    return int3(round(c * kCasterMotionScale));
}
CAUSTICS_SHARED_END

#endif  // CAUSTICS_COMMON_CASTER_MOTION_H
