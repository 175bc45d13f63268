#ifndef CAUSTICS_COMMON_OCTAHEDRAL_H
#define CAUSTICS_COMMON_OCTAHEDRAL_H
// Octahedral encoding of unit vectors (Cigolle et al. 2014, "A Survey of Efficient Representations for
// Independent Unit Vectors", JCGT 3(2)): the compact hit record's normal and incoming direction, two
// components in [-1, 1] that the caller packs as snorm16 x 2 (docs/caustics.md "Memory"; angular
// error below 1e-4 rad). One definition for GLSL, HLSL and the C++ that reads hits back.
#include "common/lang.h"

CAUSTICS_SHARED_BEGIN

CAUSTICS_FN float octSignNotZero(float v) { return v >= 0.0f ? 1.0f : -1.0f; }

CAUSTICS_FN float2 octEncode(float3 n) {
    float l1 = abs(n.x) + abs(n.y) + abs(n.z);
    float2 p = float2(n.x / l1, n.y / l1);
    if (n.z < 0.0f) p = float2((1.0f - abs(p.y)) * octSignNotZero(p.x), (1.0f - abs(p.x)) * octSignNotZero(p.y));
    return p;
}

CAUSTICS_FN float3 octDecode(float2 p) {
    float3 v = float3(p.x, p.y, 1.0f - abs(p.x) - abs(p.y));
    if (v.z < 0.0f) {
        float x = v.x;
        v.x = (1.0f - abs(v.y)) * octSignNotZero(x);
        v.y = (1.0f - abs(x)) * octSignNotZero(v.y);
    }
    return normalize(v);
}

CAUSTICS_SHARED_END

#endif
