#ifndef CAUSTICS_D3D12_CAUSTIC_HIT_HLSLI
#define CAUSTICS_D3D12_CAUSTIC_HIT_HLSLI
// The stored hit, the sphere, the trace payload and the statistics slots are the shared dialect's
// common/caustic_hit.h; here their reads and writes through byte-address buffers, for the backward
// pass's shaders.
#include "common/caustic_hit.h"
static const uint kCausticHitBytes = 64u;
static const uint kCausticSphereBytes = 64u;

CausticHit loadCausticHit(ByteAddressBuffer b, uint i) {
    return unpackCausticHit(b.Load<CausticHitRecord>(kCausticHitBytes * i));
}

void storeCausticHit(RWByteAddressBuffer b, uint i, float3 position, uint objectId, float3 normal, uint light,
                     float3 flux, float3 incoming, BrdfMaterial m) {
    b.Store<CausticHitRecord>(kCausticHitBytes * i,
                              packCausticHit(makeCausticHit(position, objectId, normal, light, flux, incoming, m)));
}

CausticSphere loadCausticSphere(ByteAddressBuffer b, uint i) { return b.Load<CausticSphere>(kCausticSphereBytes * i); }
#endif
