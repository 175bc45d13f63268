#ifndef CAUSTICS_PASS_CAUSTIC_ATROUS_THREAD_H
#define CAUSTICS_PASS_CAUSTIC_ATROUS_THREAD_H
// The thread function of caustics.atrous.N (GLSL and HLSL; the pure functions are atrous.h). A group
// of 64 threads runs one step-s lattice (atrous.h) in three phases over shared memory:
//   load     16 x 16 lattice points: pool colour and the packed guide caustics.temporal wrote once per
//            frame (depth, normal, object id, depth slope), found through this frame's slot map;
//   sources  W_q of the 12 x 12 sources the receivers read (25 weights each, from shared memory; the
//            weights stay in shared memory: 27 KB in all, under the 32 KB D3D12 and lavapipe give);
//   receive  each of the 8 x 8 receivers sums its 25 sources' shares w / W_q and writes its pool texel
//            (or, kAtrousLast, caustics.radiance).
// A point outside the view or in a tile without a pool tile holds nothing: it is neither a source nor
// a receiver (docs/caustics.md "Tiles": the energy stays in the listed tiles).
#if defined(kAtrousLast)
#include "bindings/caustic_atrous_last.h"   // generated from passes/caustic_filter/atrous_bindings.h
#else
#include "bindings/caustic_atrous.h"
#endif
#include "common/octahedral.h"
#include "common/resources.h"

FILTER_GROUPSHARED float4 sColor[kAtrousRegion * kAtrousRegion];         // rgb radiance, a deviation (pool units)
FILTER_GROUPSHARED float4 sNormalDepth[kAtrousRegion * kAtrousRegion];   // xyz normal, w linear depth
FILTER_GROUPSHARED float2 sGradient[kAtrousRegion * kAtrousRegion];      // depth slope per pixel
FILTER_GROUPSHARED uint sId[kAtrousRegion * kAtrousRegion];
FILTER_GROUPSHARED uint sSlot[kAtrousRegion * kAtrousRegion];            // kFilterNoSlot: holds nothing
FILTER_GROUPSHARED float sSourceSum[kAtrousSources * kAtrousSources];    // W_q
FILTER_GROUPSHARED float sWeight[kAtrousSources * kAtrousSources * 25];  // w(q -> q + step (dx, dy)), 5x5 row-major
FILTER_GROUPSHARED uint sFirstListed;                                    // the block's first listed tile

bool atrousListed(int2 tile, int2 tileCount) {
    if (tile.x < 0 || tile.y < 0 || tile.x >= tileCount.x || tile.y >= tileCount.y) return false;
    return CAUSTICS_TEXEL_UINT(slotMap, tile) != kFilterNoSlot;
}

uint atrousRegionIndex(int2 at) { return uint(at.y * kAtrousRegion + at.x); }

void atrousLoad(int2 origin, uint local) {
    for (uint e = local; e < uint(kAtrousRegion * kAtrousRegion); e += kFilterGroupThreads) {
        int2 point = int2(int(e) % kAtrousRegion, int(e) / kAtrousRegion) - int2(kAtrousApron, kAtrousApron);
        int2 q = atrousLatticePixel(origin, point, params.stepWidth);
        uint slot = kFilterNoSlot;
        if (filterInside(q, params.width, params.height))
            slot = CAUSTICS_TEXEL_UINT(slotMap, q / kFilterTileSize);
        sSlot[e] = slot;
        if (slot == kFilterNoSlot) continue;
        int2 t = filterPoolTexel(slot, q);
        sColor[e] = CAUSTICS_TEXEL(inColor, t);
        uint4 g = CAUSTICS_TEXEL(guides, t);   // filterPackAtrousGuide (caustics.temporal)
        float2 oct = float2(float(g.y & 0xFFFFu), float(g.y >> 16)) / 65535.0f * 2.0f - 1.0f;
        sNormalDepth[e] = float4(octDecode(oct), filterBitsToFloat(g.x));
        sId[e] = g.z;
        sGradient[e] = filterUnpackHalf2(g.w);
    }
}

// W_q of the source at region point `at` (source index `source`): the sum of its weights to the 5x5
// receivers that hold data, each kept in sWeight for the receivers' phase.
float atrousSourceSum(int2 at, uint source) {
    uint e = atrousRegionIndex(at);
    if (sSlot[e] == kFilterNoSlot || sId[e] == 0u) return 1.0f;
    float4 c = sColor[e];
    float4 nd = sNormalDepth[e];
    float total = 0.0f;
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            uint r = atrousRegionIndex(at + int2(dx, dy));
            if (sSlot[r] == kFilterNoSlot || sId[r] != sId[e]) continue;
            float4 cp = sColor[r];
            float4 ndp = sNormalDepth[r];
            float w = atrousSpreadWeight(int2(dx, dy) * params.stepWidth, params.stepWidth, nd.w, ndp.w, sGradient[e], nd.xyz,
                                         ndp.xyz, filterLuminance(c.rgb), filterLuminance(cp.rgb), c.a * c.a, cp.a * cp.a,
                                         params.sigmaLuminance);
            sWeight[source * 25u + uint((dy + 2) * 5 + dx + 2)] = w;
            total += w;
        }
    }
    return total;   // >= the centre's own weight 9/64 > 0
}

void atrousStore(int2 p, uint slot, float3 rgb, float deviation) {
#if defined(kAtrousLast)
    CAUSTICS_IMAGE_STORE(outColor, p, float4(rgb * params.invPreExposure, 1.0f));
#else
    CAUSTICS_IMAGE_STORE(outColor, filterPoolTexel(slot, p), filterNearestHalf4(float4(rgb, deviation)));
#endif
}

// Receiver `point` (0..7 per axis) of the lattice at `origin`: Var_p = sum (w / W_q)^2 Var_q goes along
// (stored as its square root).
void atrousReceive(int2 origin, int2 point) {
    int2 at = point + int2(kAtrousApron, kAtrousApron);
    uint e = atrousRegionIndex(at);
    uint slot = sSlot[e];
    if (slot == kFilterNoSlot) return;
    int2 p = atrousLatticePixel(origin, point, params.stepWidth);
    float4 centre = sColor[e];
    if (sId[e] == 0u) {
        atrousStore(p, slot, centre.rgb, centre.a);
        return;
    }
    float3 sum = float3(0.0f, 0.0f, 0.0f);
    float variance = 0.0f;
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            int2 source = at + int2(dx, dy);
            uint r = atrousRegionIndex(source);
            if (sSlot[r] == kFilterNoSlot || sId[r] != sId[e]) continue;
            float4 c = sColor[r];
            int2 s = source - int2(kAtrousApron - 2, kAtrousApron - 2);
            uint q = uint(s.y * kAtrousSources + s.x);
            // The source's weight towards this receiver, offset (-dx, -dy) from it (atrousSourceSum).
            float share = sWeight[q * 25u + uint((2 - dy) * 5 + 2 - dx)] / sSourceSum[q];
            sum += share * c.rgb;
            variance += share * share * c.a * c.a;
        }
    }
    atrousStore(p, slot, sum, sqrt(variance));
}

// One lattice, all three phases; called in uniform control flow (every thread of the group).
void atrousRunLattice(int2 origin, uint local) {
    atrousLoad(origin, local);
    FILTER_BARRIER();
    for (uint e = local; e < uint(kAtrousSources * kAtrousSources); e += kFilterGroupThreads)
        sSourceSum[e] = atrousSourceSum(int2(int(e) % kAtrousSources, int(e) / kAtrousSources) +
                                            int2(kAtrousApron - 2, kAtrousApron - 2),
                                        e);
    FILTER_BARRIER();
    atrousReceive(origin, int2(int(local) % kFilterTileSize, int(local) / kFilterTileSize));
    FILTER_BARRIER();   // the next lattice overwrites the shared arrays
}

// Group `group` runs listed tile tilesLoad(group)'s own lattice, and, if it is its block's first listed
// tile, the lattices whose designated tile is not listed (atrous.h).
void atrousThread(uint group, uint local) {
    int2 tile = filterTileOf(tilesLoad(group));
    int s = params.stepWidth;
    int2 tileCount = int2((params.width + kFilterTileSize - 1) / kFilterTileSize, (params.height + kFilterTileSize - 1) / kFilterTileSize);
    int2 block = atrousBlock(tile, s);
    if (local == 0u) sFirstListed = 0xFFFFFFFFu;
    FILTER_BARRIER();
    for (uint i = local; i < uint(s * s); i += kFilterGroupThreads)
        if (atrousListed(block * s + int2(int(i) % s, int(i) / s), tileCount)) FILTER_ATOMIC_MIN(sFirstListed, i);
    FILTER_BARRIER();
    int2 own = atrousOwnLattice(tile, s);
    atrousRunLattice(atrousLatticeOrigin(block, own, s), local);
    if (sFirstListed != uint(own.y * s + own.x)) return;
    for (int i = 0; i < s * s; ++i) {
        int2 lattice = int2(i % s, i / s);
        if (atrousListed(block * s + lattice, tileCount)) continue;   // its designated tile runs it
        atrousRunLattice(atrousLatticeOrigin(block, lattice, s), local);
    }
}

#endif  // CAUSTICS_PASS_CAUSTIC_ATROUS_THREAD_H
