#ifndef CAUSTICS_COMMON_SAMPLING_H
#define CAUSTICS_COMMON_SAMPLING_H
// Direction sampling and local frames. Local frames are z-up: (t, b, n).
#include "common/lang.h"

CAUSTICS_SHARED_BEGIN

struct Onb {
    float3 t;
    float3 b;
    float3 n;
};

// Duff, Burgess, Christensen, Hery, Kensler, Liani, Villemin 2017, "Building an orthonormal basis,
// revisited", JCGT 6(1), Listing 3: branchless, continuous except at n.z = 0 sign flip, right-handed.
CAUSTICS_FN Onb onbFromNormal(float3 n) {
    float s = n.z >= 0.0f ? 1.0f : -1.0f;
    float a = -1.0f / (s + n.z);
    float b = n.x * n.y * a;
    Onb o;
    o.t = float3(1.0f + s * n.x * n.x * a, s * b, -s * n.x);
    o.b = float3(b, s + n.y * n.y * a, -n.y);
    o.n = n;
    return o;
}

CAUSTICS_FN float3 onbToWorld(Onb o, float3 v) { return v.x * o.t + v.y * o.b + v.z * o.n; }

CAUSTICS_FN float3 onbToLocal(Onb o, float3 v) { return float3(dot(v, o.t), dot(v, o.b), dot(v, o.n)); }

// pdf = cos(theta) / pi (Malley's method: uniform disk lifted to the hemisphere).
CAUSTICS_FN float3 sampleCosineHemisphere(float2 u) {
    float r = sqrt(u.x);
    float phi = kTwoPi * u.y;
    return float3(r * cos(phi), r * sin(phi), sqrt(max(0.0f, 1.0f - u.x)));
}

CAUSTICS_FN float cosineHemispherePdf(float cosTheta) { return max(cosTheta, 0.0f) * kInvPi; }

// pdf = 1 / (4 pi).
CAUSTICS_FN float3 sampleUniformSphere(float2 u) {
    float z = 1.0f - 2.0f * u.x;
    float r = sqrt(max(0.0f, 1.0f - z * z));
    float phi = kTwoPi * u.y;
    return float3(r * cos(phi), r * sin(phi), z);
}

CAUSTICS_FN float uniformSpherePdf() { return 1.0f / (4.0f * kPi); }

// Uniform over the cone of half-angle acos(cosThetaMax) around +z; pdf = 1 / (2 pi (1 - cosThetaMax)).
CAUSTICS_FN float3 sampleUniformCone(float2 u, float cosThetaMax) {
    float cosTheta = lerp(1.0f, cosThetaMax, u.x);
    float sinTheta = sqrt(max(0.0f, 1.0f - cosTheta * cosTheta));
    float phi = kTwoPi * u.y;
    return float3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}

CAUSTICS_FN float uniformConePdf(float cosThetaMax) { return 1.0f / (kTwoPi * (1.0f - cosThetaMax)); }

CAUSTICS_SHARED_END

#endif  // CAUSTICS_COMMON_SAMPLING_H
