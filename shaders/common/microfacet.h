#ifndef CAUSTICS_COMMON_MICROFACET_H
#define CAUSTICS_COMMON_MICROFACET_H
// GGX (Trowbridge-Reitz) microfacet distribution with the separable Smith shadowing term, after
// Walter, Marschner, Li, Torrance 2007, "Microfacet models for refraction through rough surfaces"
// (EGSR), eqs. 33-36. alpha = roughness^2 (glTF 2.0 spec, Appendix B).
#include "common/lang.h"

CAUSTICS_SHARED_BEGIN

// Below this alpha the surface is treated as perfectly smooth (delta lobes).
CAUSTICS_CONST float kSmoothAlpha = 1.0e-4f;

CAUSTICS_FN float ggxAlpha(float roughness) { return roughness * roughness; }

// D(m), eq. 33; cosThetaM = m.n.
CAUSTICS_FN float ggxD(float cosThetaM, float alpha) {
    if (cosThetaM <= 0.0f) return 0.0f;
    float a2 = alpha * alpha;
    float c2 = cosThetaM * cosThetaM;
    float k = c2 * (a2 - 1.0f) + 1.0f;
    return a2 / (kPi * k * k);
}

// Smith G1(v, m), eq. 34; cosV = v.n, vDotM = v.m (the chi+ factor needs both on the same side).
CAUSTICS_FN float ggxSmithG1(float cosV, float vDotM, float alpha) {
    if (vDotM * cosV <= 0.0f) return 0.0f;
    float c2 = max(cosV * cosV, 1.0e-12f);
    float tan2 = max(0.0f, 1.0f - c2) / c2;
    return 2.0f / (1.0f + sqrt(1.0f + alpha * alpha * tan2));
}

// Microfacet normal in the local z-up frame, distributed as D(m) (m.n); eqs. 35-36.
CAUSTICS_FN float3 ggxSampleNormal(float2 u, float alpha) {
    float tan2 = alpha * alpha * u.x / max(1.0f - u.x, 1.0e-7f);
    float cosTheta = 1.0f / sqrt(1.0f + tan2);
    float sinTheta = sqrt(max(0.0f, 1.0f - cosTheta * cosTheta));
    float phi = kTwoPi * u.y;
    return float3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}

// The sample weight f |o.n| / pdf of eq. 41 when the lobe is picked with probability F:
// |i.m| G(i, o, m) / (|i.n| |m.n|). Equals 1 for a smooth surface (m = n, G = 1).
CAUSTICS_FN float ggxSampleWeight(float iDotN, float oDotN, float iDotM, float oDotM, float mDotN, float alpha) {
    float g = ggxSmithG1(iDotN, iDotM, alpha) * ggxSmithG1(oDotN, oDotM, alpha);
    return abs(iDotM) * g / max(abs(iDotN) * abs(mDotN), 1.0e-12f);
}

CAUSTICS_SHARED_END

#endif  // CAUSTICS_COMMON_MICROFACET_H
