#ifndef CAUSTICS_PASS_CAUSTIC_ATROUS_THREAD_H
#define CAUSTICS_PASS_CAUSTIC_ATROUS_THREAD_H
// The thread function of caustics.atrous.N.pairs (kAtrousPairs) and caustics.atrous.N (GLSL and HLSL; the
// pure functions are atrous.h). One 8x8 group per listed tile (the group index is the tile's pool tile);
// each tap's colour and guide are fetched (a group-shared region of the tile's colours and guides and its
// apron measured 3-4x slower on the H200: docs/caustics.md "Cost"), the taps' pool tiles read from the
// slot map once per group into group-shared memory (sSlots):
//   pairs    w(p, p + s tap_k) for the 12 later neighbours tap_k of each pixel (atrousPairTap), packed;
//            0 where the neighbour holds no data, has another object or both are dark (no source); each
//            pair's weight is added to both pixels' W in fixed point (buffer atomics on this iteration's
//            region of caustics.atrous.sums, one word per pool texel, zeroed before), with the centre tap
//            to the pixel's own;
//   shares   each pixel receives w(p, q) / W_q of its 5x5 sources, skipping zero pairs before any fetch
//            and dark sources after one colour fetch, and zeroes its word of the next iteration's sums
//            (or, kAtrousLast, writes caustics.radiance).
// A pixel outside the view or in a tile without a pool tile holds nothing: it is neither a source nor a
// receiver (docs/caustics.md "Tiles": the energy stays in the listed tiles).
#if defined(kAtrousPairs)
#include "bindings/caustic_atrous_pairs.h"   // generated from passes/caustic_filter/atrous_bindings.h
#elif defined(kAtrousLast)
#include "bindings/caustic_atrous_last.h"
#else
#include "bindings/caustic_atrous.h"
#endif
#include "common/octahedral.h"
#include "common/resources.h"

// The 5x5 tap loops unrolled: each tap's kernel weight and offset become constants (the GLSL entries
// enable GL_EXT_control_flow_attributes).
#if defined(CAUSTICS_LANG_HLSL)
#define ATROUS_UNROLL [unroll]
#else
#define ATROUS_UNROLL [[unroll]]
#endif

// The pool tiles that hold the group's taps (kFilterNoSlot outside the view or where a tile has none),
// read once per group (atrousLoadSlots) instead of once per tap. A step up to kFilterTileSize / 2 keeps
// every tap in the group's tile and its 8 neighbours: sSlots[0..8] holds them row by row from the one
// above left. From kFilterTileSize on (the fourth iteration and later), tap (dx, dy) of every pixel of
// the group lies in the tile (dx, dy) x step / kFilterTileSize away: sSlots holds the 25, by tap.
CAUSTICS_GROUPSHARED uint sSlots[25];

bool atrousSlotsByTap() { return params.stepWidth >= kFilterTileSize; }

// Fills sSlots and returns the group's screen tile. Every thread of the group calls it (a barrier).
int2 atrousLoadSlots(uint group, uint local) {
    int2 tile = filterTileOf(tilesLoad(group));
    int2 t = atrousSlotsByTap() ? tile + int2(int(local % 5u) - 2, int(local / 5u) - 2) * (params.stepWidth >> kFilterTileShift)
                                : tile + int2(int(local % 3u) - 1, int(local / 3u) - 1);
    if (local < (atrousSlotsByTap() ? 25u : 9u)) {
        int2 tiles = int2((params.width + kFilterTileSize - 1) >> kFilterTileShift, (params.height + kFilterTileSize - 1) >> kFilterTileShift);
        sSlots[local] = filterInside(t, tiles.x, tiles.y) ? CAUSTICS_TEXEL_UINT(slotMap, t) : kFilterNoSlot;
    }
    CAUSTICS_GROUP_BARRIER();
    return tile;
}

// The pool tile of screen pixel q = p + step tap, p a pixel of the group's tile `tile` (sSlots), or
// kFilterNoSlot where q is outside the view or its tile has no pool tile.
uint atrousSlot(int2 q, int2 tile, int2 tap) {
    if (!filterInside(q, params.width, params.height)) return kFilterNoSlot;
    if (atrousSlotsByTap()) return sSlots[(tap.y + 2) * 5 + tap.x + 2];
    int2 near = filterTileOfPixel(q) - tile + int2(1, 1);
    return sSlots[near.y * 3 + near.x];
}

// Pixel p's word in this iteration's region of caustics.atrous.sums.
uint atrousSumIndex(uint slot, int2 p) { return filterPoolWord(params.sumsBase, slot, p); }

bool atrousIsDark(float4 c) { return c.x == 0.0f && c.y == 0.0f && c.z == 0.0f && c.w == 0.0f; }

#if defined(kAtrousPairs)
// A pixel's guide (filterPackAtrousGuide, caustics.temporal): normal, linear depth, id, depth slope. Only
// the pairs pass reads guides.
struct AtrousGuide {
    float3 normal;
    float depth;
    uint id;   // 0 = no surface
    float2 gradient;
};

AtrousGuide atrousGuide(int2 t) {
    uint4 g = CAUSTICS_TEXEL(guides, t);
    float2 oct = float2(float(g.y & 0xFFFFu), float(g.y >> 16)) / 65535.0f * 2.0f - 1.0f;
    AtrousGuide a;
    a.normal = octDecode(oct);
    a.depth = filterBitsToFloat(g.x);
    a.id = g.z;
    a.gradient = filterUnpackHalf2(g.w);
    return a;
}

void atrousThread(uint group, uint local) {
    int s = params.stepWidth;
    int2 tile = atrousLoadSlots(group, local);
    int2 p = tile * kFilterTileSize + int2(int(local % 8u), int(local / 8u));
    if (!filterInside(p, params.width, params.height)) return;
    int2 own = filterPoolTexel(group, p);   // list index = pool tile (tile_list_thread.h)
    float4 centreColor = CAUSTICS_TEXEL(inColor, own);
    AtrousGuide centre = atrousGuide(own);
    uint4 pairs = uint4(0u, 0u, 0u, 0u);
    uint sum = atrousFixedWeight(kAtrousSelfWeight);
    if (centre.id != 0u) {
        bool centreDark = atrousIsDark(centreColor);
        float lp = filterLuminance(centreColor.rgb), vp = centreColor.a * centreColor.a;
        ATROUS_UNROLL for (int k = 0; k < kAtrousPairCount; ++k) {
            int2 tap = atrousPairTap(k), q = p + tap * s;
            uint slot = atrousSlot(q, tile, tap);
            if (slot == kFilterNoSlot) continue;
            int2 t = filterPoolTexel(slot, q);
            // The guide with the colour, before the tests on either: the taps' fetches overlap.
            float4 c = CAUSTICS_TEXEL(inColor, t);
            AtrousGuide g = atrousGuide(t);
            if (centreDark && atrousIsDark(c)) continue;   // neither hands anything to the other
            if (g.id != centre.id) continue;
            uint code = atrousPackWeight(atrousPairWeight(tap, s, centre.depth, g.depth, centre.gradient, g.gradient, centre.normal,
                                                          g.normal, lp, filterLuminance(c.rgb), vp, c.a * c.a,
                                                          params.sigmaLuminance, params.depthJitter));
            if (code == 0u) continue;
            pairs[k / 3] |= code << (10 * (k % 3));
            uint fixedWeight = atrousFixedWeight(atrousUnpackWeight(code));
            sum += fixedWeight;
            weightSumsAtomicAdd(atrousSumIndex(slot, q), fixedWeight);
        }
    }
    CAUSTICS_IMAGE_STORE(outPairs, own, pairs);
    weightSumsAtomicAdd(atrousSumIndex(group, p), sum);
}
#else
void atrousStore(int2 p, int2 own, float3 rgb, float deviation) {
#if defined(kAtrousLast)
    int2 target = SPECULAR_INPUT_TEXEL(p, FILTER_LIST_ORDER_ON);
    if (target.x >= 0) CAUSTICS_IMAGE_STORE(outColor, target, float4(rgb * params.invPreExposure, 1.0f));
#else
    CAUSTICS_IMAGE_STORE(outColor, own, filterNearestHalf4(float4(rgb, deviation)));
#endif
}

// Source q's share w / W_q of its colour, added to a receiver's sum (rgb) and variance; a dark source
// gives nothing.
void atrousAddShare(uint slot, int2 q, float w, CAUSTICS_INOUT(float3) sum, CAUSTICS_INOUT(float) variance) {
    float4 c = CAUSTICS_TEXEL(inColor, filterPoolTexel(slot, q));
    if (atrousIsDark(c)) return;
    float share = w * kAtrousFixedScale / float(weightSumsLoad(atrousSumIndex(slot, q)));
    sum += share * c.rgb;
    variance += share * share * (c.a * c.a);
}

void atrousThread(uint group, uint local) {
    int s = params.stepWidth;
    int2 tile = atrousLoadSlots(group, local);
    int2 p = tile * kFilterTileSize + int2(int(local % 8u), int(local / 8u));
    if (!filterInside(p, params.width, params.height)) return;
    int2 own = filterPoolTexel(group, p);
#if !defined(kAtrousLast)
    // The next iteration's pairs pass adds into that word; every texel this pass reads W from is a listed
    // pixel in the view, so every one of those is zeroed here (iteration i - 1 read it last pass).
    weightSumsStore(filterPoolWord(params.nextSumsBase, group, p), 0u);
#endif
    // A pixel without a surface (id 0) has no pair and no pair names it, so its W is the centre tap's and
    // it keeps its colour through the same sum: no guide fetch here.
    float3 sum = float3(0.0f, 0.0f, 0.0f);
    float variance = 0.0f;
    atrousAddShare(group, p, kAtrousSelfWeight, sum, variance);
    uint4 ownPairs = CAUSTICS_TEXEL(pairs, own);
    ATROUS_UNROLL for (int k = 0; k < kAtrousPairCount; ++k) {
        // The later neighbour: the pair is this pixel's own (non-zero only where the neighbour is in the pool).
        int2 tap = atrousPairTap(k), q = p + tap * s;
        uint code = atrousPairCode(ownPairs, k);
        if (code != 0u) atrousAddShare(atrousSlot(q, tile, tap), q, atrousUnpackWeight(code), sum, variance);
        // The earlier neighbour holds the pair at the same index.
        q = p - tap * s;
        uint slot = atrousSlot(q, tile, -tap);
        if (slot == kFilterNoSlot) continue;
        code = atrousPairCode(CAUSTICS_TEXEL(pairs, filterPoolTexel(slot, q)), k);
        if (code != 0u) atrousAddShare(slot, q, atrousUnpackWeight(code), sum, variance);
    }
    atrousStore(p, own, sum, sqrt(variance));
}
#endif

#endif  // CAUSTICS_PASS_CAUSTIC_ATROUS_THREAD_H
