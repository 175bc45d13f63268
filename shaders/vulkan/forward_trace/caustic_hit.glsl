#ifndef CAUSTICS_CAUSTIC_HIT_GLSL
#define CAUSTICS_CAUSTIC_HIT_GLSL
// std430 mirrors of caustics::CausticHit (the 64-byte CausticHitRecord here) / CausticSphere
// (passes/include/caustics/caustic_passes.h) and the statistics slots. Shaders work on the unpacked
// CausticHit; the buffer holds records (packCausticHit / unpackCausticHit).
#include "common/bsdf.h"
#include "common/octahedral.h"
struct CausticHit {
    vec3 position;  uint objectId;
    vec3 normal;    uint light;              // normal: unit, on the side the photon arrived from
    vec3 flux;      uint metallicRoughness;  // flux: lm; unorm16 x 2 (metallic low, roughness high)
    vec3 incoming;  float transmission;      // incoming: unit, back along the photon's last segment
    vec3 baseColor; float dielectricF0;
};
struct CausticHitRecord {
    vec3 position;  uint objectId;
    vec3 flux;      uint light;
    vec3 baseColor; float dielectricF0;
    uint normal;    uint incoming;           // octahedral snorm16 x 2 (common/octahedral.h)
    uint metallicRoughness; float transmission;
};

CausticHitRecord packCausticHit(CausticHit h) {
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

CausticHit unpackCausticHit(CausticHitRecord r) {
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

CausticHit makeCausticHit(vec3 position, uint objectId, vec3 normal, uint light, vec3 flux, vec3 incoming,
                          BrdfMaterial m) {
    CausticHit h;
    h.position = position;
    h.objectId = objectId;
    h.normal = normal;
    h.light = light;
    h.flux = flux;
    h.metallicRoughness = packUnorm2x16(vec2(m.metallic, m.roughness));
    h.incoming = incoming;
    h.transmission = m.transmission;
    h.baseColor = m.baseColor;
    h.dielectricF0 = m.dielectricF0;
    return h;
}

// The receiver's BRDF parameters (shaders/common/bsdf.h) as the forward trace stored them.
BrdfMaterial causticHitBrdf(CausticHit h) {
    vec2 mr = unpackUnorm2x16(h.metallicRoughness);
    return makeBrdfMaterial(h.baseColor, mr.x, mr.y, h.transmission, h.dielectricF0);
}

// Reflected radiance-weighted flux flux x f_r(wi, wo) towards wo (lm / sr per channel).
vec3 causticHitReflectedFlux(CausticHit h, vec3 wo) {
    return h.flux * evalGltfBrdf(causticHitBrdf(h), h.normal, h.incoming, wo);
}
struct CausticSphere {
    vec3 centre;        float radius;
    vec3 transmittance; uint objectId;
    vec3 normal;        uint pixel;
    vec3 outgoing;      float pad;  // unit, from the receiver back along the camera path (BRDF wo)
};
const uint kStatStoredHitAttempts = 0u;
const uint kStatSplats = 1u;
const uint kStatGatherHits = 2u;
const uint kStatSpheres = 3u;
const uint kStatRaysPerLight = 4u;
const uint kStatAccumulationGiveUps = 68u;   // kStatForwardSegments + 4 (caustic_passes.h); only HLSL's CAS loop counts
const uint kStatSaturatedAdds = 73u;         // fixed-point adds that pinned a word at its maximum
const uint kStatFixedPointScale = 74u;       // float bits: value x this = fixed-point word (written by the host)

// Closest-hit payload of trace.rchit / trace.rmiss: t < 0 = miss.
struct TracePayload {
    vec2 barycentrics;
    uint instance;
    uint primitive;
    float t;
};

// Surface offset for continuing rays, relative to the coordinates' magnitude (float spacing).
float rayEpsilon(vec3 p) { return 1e-4 * (1.0 + max(abs(p.x), max(abs(p.y), abs(p.z)))); }
#endif
