#ifndef CAUSTICS_COMMON_CAUSTIC_HIT_H
#define CAUSTICS_COMMON_CAUSTIC_HIT_H
// The forward trace's stored diffuse hit and the backward pass's sphere, in the shared dialect (the
// forward pass writes hits, the backward pass reads them; docs/shaders.md). CausticHitRecord is the
// 64-byte std430 record of caustics::CausticHit (passes/internal/caustics/caustic_passes.h): its
// normal and incoming direction are octahedral snorm16 x 2 (common/octahedral.h). Shaders work on the
// unpacked CausticHit (packCausticHit / unpackCausticHit).
#include "common/bsdf.h"
#include "common/caustic_stats.h"
#include "common/octahedral.h"

CAUSTICS_SHARED_BEGIN
struct CausticHit {
    float3 position;  uint objectId;
    float3 normal;    uint light;              // normal: unit, on the side the photon arrived from
    float3 flux;      uint metallicRoughness;  // flux: lm; unorm16 x 2 (metallic low, roughness high)
    float3 incoming;  float transmission;      // incoming: unit, back along the photon's last segment
    float3 baseColor; float dielectricF0;
};
struct CausticHitRecord {   // 64 bytes
    float3 position;  uint objectId;
    float3 flux;      uint light;
    float3 baseColor; float dielectricF0;
    uint normal;      uint incoming;           // octahedral snorm16 x 2
    uint metallicRoughness; float transmission;
};
struct CausticSphere {      // 64 bytes
    float3 centre;        float radius;
    float3 transmittance; uint objectId;
    float3 normal;        uint pixel;
    float3 outgoing;      uint likelyPath;   // outgoing: unit, from the receiver back along the camera path
                                             // (BRDF wo); likelyPath: 1 when every specular event took its
                                             // most probable lobe (docs/caustics.md "Second-type guides")
};

// Closest-hit payload of the scene traces (scene_trace/trace.rchit, trace.rmiss): t < 0 = miss.
struct TracePayload {
    float2 barycentrics;
    uint instance;
    uint primitive;
    float t;
};

CAUSTICS_FN CausticHitRecord packCausticHit(CausticHit h) {
    CausticHitRecord r;
    r.position = h.position;
    r.objectId = h.objectId;
    r.flux = h.flux;
    r.light = h.light;
    r.baseColor = h.baseColor;
    r.dielectricF0 = h.dielectricF0;
    r.normal = packSnorm2x16(octEncode(h.normal));
    r.incoming = packSnorm2x16(octEncode(h.incoming));
    r.metallicRoughness = h.metallicRoughness;
    r.transmission = h.transmission;
    return r;
}

CAUSTICS_FN CausticHit unpackCausticHit(CausticHitRecord r) {
    CausticHit h;
    h.position = r.position;
    h.objectId = r.objectId;
    h.normal = octDecode(unpackSnorm2x16(r.normal));
    h.light = r.light;
    h.flux = r.flux;
    h.metallicRoughness = r.metallicRoughness;
    h.incoming = octDecode(unpackSnorm2x16(r.incoming));
    h.transmission = r.transmission;
    h.baseColor = r.baseColor;
    h.dielectricF0 = r.dielectricF0;
    return h;
}

CAUSTICS_FN CausticHit makeCausticHit(float3 position, uint objectId, float3 normal, uint light, float3 flux,
                                      float3 incoming, BrdfMaterial m) {
    CausticHit h;
    h.position = position;
    h.objectId = objectId;
    h.normal = normal;
    h.light = light;
    h.flux = flux;
    h.metallicRoughness = packUnorm2x16(float2(m.metallic, m.roughness));
    h.incoming = incoming;
    h.transmission = m.transmission;
    h.baseColor = m.baseColor;
    h.dielectricF0 = m.dielectricF0;
    return h;
}

// The receiver's BRDF parameters (shaders/common/bsdf.h) as the forward trace stored them.
CAUSTICS_FN BrdfMaterial causticHitBrdf(CausticHit h) {
    float2 mr = unpackUnorm2x16(h.metallicRoughness);
    return makeBrdfMaterial(h.baseColor, mr.x, mr.y, h.transmission, h.dielectricF0);
}

// Reflected radiance-weighted flux flux x f_r(wi, wo) towards wo (lm / sr per channel).
CAUSTICS_FN float3 causticHitReflectedFlux(CausticHit h, float3 wo) {
    return h.flux * evalGltfBrdf(causticHitBrdf(h), h.normal, h.incoming, wo);
}

// Surface offset for continuing rays, relative to the coordinates' magnitude (float spacing).
CAUSTICS_FN float rayEpsilon(float3 p) { return 1e-4f * (1.0f + max(abs(p.x), max(abs(p.y), abs(p.z)))); }
CAUSTICS_SHARED_END

#endif  // CAUSTICS_COMMON_CAUSTIC_HIT_H
