#ifndef CAUSTICS_D3D12_CAUSTIC_HIT_HLSLI
#define CAUSTICS_D3D12_CAUSTIC_HIT_HLSLI
// std430 CausticHit / CausticSphere (48 bytes each) and the statistics slots (mirror of
// shaders/vulkan/forward_trace/caustic_hit.glsl), read/written through byte-address buffers.
struct CausticHit { float3 position; uint objectId; float3 normal; uint light; float3 fluxBsdf; };
struct CausticSphere { float3 centre; float radius; float3 transmittance; uint objectId; float3 normal; uint pixel; };

static const uint kStatStoredHitAttempts = 0u;
static const uint kStatSplats = 1u;
static const uint kStatGatherHits = 2u;
static const uint kStatSpheres = 3u;
static const uint kStatRaysPerLight = 4u;

struct TracePayload {   // t < 0 = miss
    float2 barycentrics;
    uint instance;
    uint primitive;
    float t;
};

CausticHit loadCausticHit(ByteAddressBuffer b, uint i) {
    uint o = 48u * i;
    uint4 a = b.Load4(o), n = b.Load4(o + 16u), f = b.Load4(o + 32u);
    CausticHit h;
    h.position = asfloat(a.xyz); h.objectId = a.w;
    h.normal = asfloat(n.xyz); h.light = n.w;
    h.fluxBsdf = asfloat(f.xyz);
    return h;
}

CausticSphere loadCausticSphere(ByteAddressBuffer b, uint i) {
    uint o = 48u * i;
    uint4 a = b.Load4(o), t = b.Load4(o + 16u), n = b.Load4(o + 32u);
    CausticSphere s;
    s.centre = asfloat(a.xyz); s.radius = asfloat(a.w);
    s.transmittance = asfloat(t.xyz); s.objectId = t.w;
    s.normal = asfloat(n.xyz); s.pixel = n.w;
    return s;
}

float rayEpsilon(float3 p) { return 1e-4f * (1.0f + max(abs(p.x), max(abs(p.y), abs(p.z)))); }
#endif
