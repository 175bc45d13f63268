#ifndef CAUSTICS_D3D12_CAUSTIC_HIT_HLSLI
#define CAUSTICS_D3D12_CAUSTIC_HIT_HLSLI
// std430 CausticHit record (64 bytes) / CausticSphere (64 bytes) and the statistics slots (mirror of
// shaders/vulkan/forward_trace/caustic_hit.glsl), read/written through byte-address buffers; the
// record's normal and incoming direction are octahedral snorm16 x 2 (common/octahedral.h).
#include "common/bsdf.h"
#include "common/octahedral.h"
struct CausticHit {
    float3 position;  uint objectId;
    float3 normal;    uint light;              // normal: unit, on the side the photon arrived from
    float3 flux;      uint metallicRoughness;  // flux: lm; unorm16 x 2 (metallic low, roughness high)
    float3 incoming;  float transmission;      // incoming: unit, back along the photon's last segment
    float3 baseColor; float dielectricF0;
};
static const uint kCausticHitBytes = 64u;

// GLSL packUnorm2x16 / unpackUnorm2x16.
uint packUnorm2x16(float2 v) {
    uint2 q = uint2(round(saturate(v) * 65535.0f));
    return q.x | (q.y << 16);
}
float2 unpackUnorm2x16(uint p) { return float2(p & 0xFFFFu, p >> 16) / 65535.0f; }
// GLSL packSnorm2x16 / unpackSnorm2x16 (round(clamp(v, -1, 1) x 32767), two's complement halves).
uint packSnorm2x16(float2 v) {
    int2 q = int2(round(clamp(v, -1.0f, 1.0f) * 32767.0f));
    return (uint(q.x) & 0xFFFFu) | (uint(q.y) << 16);
}
float2 unpackSnorm2x16(uint p) {
    int2 q = int2(int(p << 16) >> 16, int(p) >> 16);
    return clamp(float2(q) / 32767.0f, -1.0f, 1.0f);
}
struct CausticSphere {   // 64 bytes
    float3 centre; float radius; float3 transmittance; uint objectId; float3 normal; uint pixel; float3 outgoing;
};
static const uint kCausticSphereBytes = 64u;

static const uint kStatStoredHitAttempts = 0u;
static const uint kStatSplats = 1u;
static const uint kStatGatherHits = 2u;
static const uint kStatSpheres = 3u;
static const uint kStatRaysPerLight = 4u;
static const uint kStatAccumulationGiveUps = 68u;   // kStatForwardSegments + 4 (caustic_passes.h)
static const uint kStatSaturatedAdds = 73u;         // fixed-point adds that pinned a word at its maximum
static const uint kStatFixedPointScale = 74u;       // float bits: value x this = fixed-point word (host-written)

struct TracePayload {   // t < 0 = miss
    float2 barycentrics;
    uint instance;
    uint primitive;
    float t;
};

CausticHit loadCausticHit(ByteAddressBuffer b, uint i) {
    uint o = kCausticHitBytes * i;
    uint4 a = b.Load4(o), f = b.Load4(o + 16u), c = b.Load4(o + 32u), d = b.Load4(o + 48u);
    CausticHit h;
    h.position = asfloat(a.xyz); h.objectId = a.w;
    h.flux = asfloat(f.xyz); h.light = f.w;
    h.baseColor = asfloat(c.xyz); h.dielectricF0 = asfloat(c.w);
    h.normal = octDecode(unpackSnorm2x16(d.x));
    h.incoming = octDecode(unpackSnorm2x16(d.y));
    h.metallicRoughness = d.z; h.transmission = asfloat(d.w);
    return h;
}

void storeCausticHit(RWByteAddressBuffer b, uint i, float3 position, uint objectId, float3 normal, uint light,
                     float3 flux, float3 incoming, BrdfMaterial m) {
    uint o = kCausticHitBytes * i;
    b.Store4(o, uint4(asuint(position), objectId));
    b.Store4(o + 16u, uint4(asuint(flux), light));
    b.Store4(o + 32u, uint4(asuint(m.baseColor), asuint(m.dielectricF0)));
    b.Store4(o + 48u, uint4(packSnorm2x16(octEncode(normal)), packSnorm2x16(octEncode(incoming)),
                            packUnorm2x16(float2(m.metallic, m.roughness)), asuint(m.transmission)));
}

// The receiver's BRDF parameters (shaders/common/bsdf.h) as the forward trace stored them.
BrdfMaterial causticHitBrdf(CausticHit h) {
    float2 mr = unpackUnorm2x16(h.metallicRoughness);
    return makeBrdfMaterial(h.baseColor, mr.x, mr.y, h.transmission, h.dielectricF0);
}

// Reflected flux x f_r(wi, wo) towards wo (lm / sr per channel).
float3 causticHitReflectedFlux(CausticHit h, float3 wo) {
    return h.flux * evalGltfBrdf(causticHitBrdf(h), h.normal, h.incoming, wo);
}

CausticSphere loadCausticSphere(ByteAddressBuffer b, uint i) {
    uint o = kCausticSphereBytes * i;
    uint4 a = b.Load4(o), t = b.Load4(o + 16u), n = b.Load4(o + 32u);
    CausticSphere s;
    s.centre = asfloat(a.xyz); s.radius = asfloat(a.w);
    s.transmittance = asfloat(t.xyz); s.objectId = t.w;
    s.normal = asfloat(n.xyz); s.pixel = n.w;
    s.outgoing = asfloat(b.Load3(o + 48u));
    return s;
}

float rayEpsilon(float3 p) { return 1e-4f * (1.0f + max(abs(p.x), max(abs(p.y), abs(p.z)))); }
#endif
