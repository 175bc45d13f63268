#ifndef CAUSTICS_COMMON_FRESNEL_H
#define CAUSTICS_COMMON_FRESNEL_H
// Fresnel reflectance and Snell refraction (Born & Wolf, Principles of Optics, sec. 1.5.2).
// Conventions: cosThetaI >= 0 is measured on the incident side of the interface; eta = etaT / etaI
// (transmitted over incident medium), so eta > 1 when light enters glass from air.
#include "common/lang.h"

CAUSTICS_SHARED_BEGIN

// Power reflectances (Rs, Rp) for s- and p-polarised light; (1, 1) under total internal reflection.
CAUSTICS_FN float2 fresnelDielectricPolarized(float cosThetaI, float eta) {
    float c = saturate(cosThetaI);
    float sin2T = (1.0f - c * c) / (eta * eta);
    if (sin2T >= 1.0f) return float2(1.0f, 1.0f);
    float cosT = sqrt(1.0f - sin2T);
    // Amplitude coefficients divided through by etaI: rs = (ni ci - nt ct)/(ni ci + nt ct), etc.
    float rs = (c - eta * cosT) / (c + eta * cosT);
    float rp = (eta * c - cosT) / (eta * c + cosT);
    return float2(rs * rs, rp * rp);
}

// Exact unpolarised reflectance: the mean of Rs and Rp. Transmittance is 1 - R (no absorption at the
// interface itself).
CAUSTICS_FN float fresnelDielectric(float cosThetaI, float eta) {
    float2 r = fresnelDielectricPolarized(cosThetaI, eta);
    return 0.5f * (r.x + r.y);
}

// Thin-walled glass (glTF transmission without KHR_materials_volume) is a pane: two parallel interfaces
// and a lossless inside (glTF gives a thin wall no thickness to absorb over). Each face reflects R from
// either side (Stokes relations r' = -r, t t' = 1 - r^2) and the light between the faces is summed over
// all inner reflections, a geometric series in R^2:
//   R' = R + (1 - R)^2 R / (1 - R^2) = 2R / (1 + R),   T' = (1 - R)^2 / (1 - R^2) = (1 - R) / (1 + R).
// s and p do not mix at parallel planar faces, so the series is summed per polarisation and then
// averaged (docs/physics.md "Thin-walled glass"). ior: the pane's index against the outside (air).
CAUSTICS_FN float thinPaneReflectance(float cosThetaI, float ior) {
    float2 r = fresnelDielectricPolarized(cosThetaI, ior);
    return r.x / (1.0f + r.x) + r.y / (1.0f + r.y);
}

// Normal-incidence reflectance ((eta - 1) / (eta + 1))^2.
CAUSTICS_FN float dielectricF0(float eta) {
    float r = (eta - 1.0f) / (eta + 1.0f);
    return r * r;
}

// Conductors use Schlick's approximation with the glTF base colour as F0 (glTF 2.0 spec, Appendix B,
// "metal_brdf": F = F0 + (1 - F0)(1 - |V.H|)^5). glTF stores no complex IOR, so the exact conductor
// Fresnel has no data to work from.
CAUSTICS_FN float3 fresnelSchlick(float3 f0, float cosTheta) {
    float m = saturate(1.0f - cosTheta);
    float m2 = m * m;
    return f0 + (splat3(1.0f) - f0) * (m2 * m2 * m);
}

// Snell's law. d: unit propagation direction towards the surface; n: unit normal with dot(d, n) < 0;
// etaRatio = etaI / etaT. Returns false under total internal reflection.
CAUSTICS_FN bool refractDirection(float3 d, float3 n, float etaRatio, CAUSTICS_OUT(float3) t) {
    float cosI = -dot(d, n);
    float sin2T = etaRatio * etaRatio * max(0.0f, 1.0f - cosI * cosI);
    if (sin2T >= 1.0f) {
        t = splat3(0.0f);
        return false;
    }
    float cosT = sqrt(1.0f - sin2T);
    t = normalize(etaRatio * d + (etaRatio * cosI - cosT) * n);
    return true;
}

CAUSTICS_SHARED_END

#endif  // CAUSTICS_COMMON_FRESNEL_H
