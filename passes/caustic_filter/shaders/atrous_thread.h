#ifndef CAUSTICS_PASS_CAUSTIC_ATROUS_THREAD_H
#define CAUSTICS_PASS_CAUSTIC_ATROUS_THREAD_H
// The thread function of caustics.atrous.N and caustics.atrous.N.weights (GLSL and HLSL; the pure
// functions are atrous.h). One 8x8 group per listed tile (the group index is the tile's pool tile):
//   load     up to step kAtrousSharedMaxStep, the region (the tile and a 2-step apron) into shared
//            memory: the packed guide (caustics.temporal, decoded once here), the colour and, for the
//            shares, 1 / W_q, found through the 3x3 slot-map entries around the tile;
//   weights  kAtrousWeights: W_q of the group's pixels, the sum of their weights to the 5x5 receivers
//            that hold data;
//   shares   otherwise: each pixel receives w(q -> p) / W_q of its 5x5 sources (or, kAtrousLast, writes
//            caustics.radiance).
// A pixel outside the view or in a tile without a pool tile holds nothing: it is neither a source nor a
// receiver (docs/caustics.md "Tiles": the energy stays in the listed tiles). A region in which every
// colour is zero gives zeros (and W = 1, which nothing divides): the group skips the weights.
#if defined(kAtrousWeights)
#include "bindings/caustic_atrous_weights.h"   // generated from passes/caustic_filter/atrous_bindings.h
#elif defined(kAtrousLast)
#include "bindings/caustic_atrous_last.h"
#else
#include "bindings/caustic_atrous.h"
#endif
#include "common/octahedral.h"
#include "common/resources.h"

// One pixel's filter inputs. valid: inside the view and in a tile with a pool tile.
struct AtrousPoint {
    float4 normalDepth;   // xyz the normal, w the linear depth
    float4 color;         // rgb radiance, a deviation of the mean (pool units)
    float2 gradient;      // depth slope
    uint id;              // object id, 0 = no surface
    float invSum;         // 1 / W_q (the shares pass)
    bool valid;
};

CAUSTICS_CONST int kAtrousRegionPoints = kAtrousMaxRegionSide * kAtrousMaxRegionSide;
CAUSTICS_CONST uint kAtrousNoData = 0xFFFFFFFFu;   // sIdValid of a point that holds nothing
FILTER_GROUPSHARED float4 sNormalDepth[kAtrousRegionPoints];
FILTER_GROUPSHARED uint2 sColor[kAtrousRegionPoints];      // 4 x half: the pool's RGBA16F, exact
FILTER_GROUPSHARED uint2 sIdGradient[kAtrousRegionPoints]; // x the id (kAtrousNoData: nothing), y 2 x half slope
#if !defined(kAtrousWeights)
FILTER_GROUPSHARED float sInvSum[kAtrousRegionPoints];
#endif
FILTER_GROUPSHARED uint sSlots[9];     // the 3x3 tiles around the group's
FILTER_GROUPSHARED uint sAnyLight;     // 1 when some colour of the region is not zero

uint atrousSlotMapEntry(int2 tile) {
    int2 tiles = int2((params.width + kFilterTileSize - 1) / kFilterTileSize, (params.height + kFilterTileSize - 1) / kFilterTileSize);
    if (tile.x < 0 || tile.y < 0 || tile.x >= tiles.x || tile.y >= tiles.y) return kFilterNoSlot;
    return CAUSTICS_TEXEL_UINT(slotMap, tile);
}

AtrousPoint atrousFetch(int2 p, uint slot) {
    AtrousPoint a;
    a.valid = slot != kFilterNoSlot && filterInside(p, params.width, params.height);
    a.normalDepth = float4(0.0f, 0.0f, 1.0f, 0.0f);
    a.color = float4(0.0f, 0.0f, 0.0f, 0.0f);
    a.gradient = float2(0.0f, 0.0f);
    a.id = 0u;
    a.invSum = 1.0f;
    if (!a.valid) return a;
    int2 t = filterPoolTexel(slot, p);
    uint4 g = CAUSTICS_TEXEL(guides, t);   // filterPackAtrousGuide (caustics.temporal)
    float2 oct = float2(float(g.y & 0xFFFFu), float(g.y >> 16)) / 65535.0f * 2.0f - 1.0f;
    a.normalDepth = float4(octDecode(oct), filterBitsToFloat(g.x));
    a.id = g.z;
    a.gradient = filterUnpackHalf2(g.w);
    a.color = CAUSTICS_TEXEL(inColor, t);
#if !defined(kAtrousWeights)
    a.invSum = 1.0f / CAUSTICS_TEXEL(sums, t).x;
#endif
    return a;
}

// The point at pixel p: from the region (p inside it) or fetched (steps past kAtrousSharedMaxStep).
AtrousPoint atrousPoint(int2 p, int2 regionOrigin, bool region) {
    if (!region) return atrousFetch(p, filterInside(p, params.width, params.height) ? atrousSlotMapEntry(p / kFilterTileSize) : kFilterNoSlot);
    int side = atrousRegionSide(params.stepWidth);
    int2 at = p - regionOrigin;
    uint e = uint(at.y * side + at.x);
    AtrousPoint a;
    a.valid = sIdGradient[e].x != kAtrousNoData;
    a.normalDepth = sNormalDepth[e];
    a.color = float4(filterUnpackHalf2(sColor[e].x), filterUnpackHalf2(sColor[e].y));
    a.id = sIdGradient[e].x;
    a.gradient = filterUnpackHalf2(sIdGradient[e].y);
#if !defined(kAtrousWeights)
    a.invSum = sInvSum[e];
#else
    a.invSum = 1.0f;
#endif
    return a;
}

// Loads the group's region; called in uniform control flow.
void atrousLoadRegion(int2 tile, int2 regionOrigin, uint local) {
    if (local < 9u) sSlots[local] = atrousSlotMapEntry(tile + int2(int(local % 3u), int(local / 3u)) - int2(1, 1));
    if (local == 0u) sAnyLight = 0u;
    FILTER_BARRIER();
    int side = atrousRegionSide(params.stepWidth);
    uint anyLight = 0u;
    for (uint e = local; e < uint(side * side); e += kFilterGroupThreads) {
        int2 p = regionOrigin + int2(int(e) % side, int(e) / side);
        uint slot = filterInside(p, params.width, params.height) ? sSlots[atrousNeighbourTileIndex(p / kFilterTileSize, tile)] : kFilterNoSlot;
        AtrousPoint a = atrousFetch(p, slot);
        sNormalDepth[e] = a.normalDepth;
        sColor[e] = uint2(filterPackHalf2(a.color.xy), filterPackHalf2(a.color.zw));
        sIdGradient[e] = uint2(a.valid ? a.id : kAtrousNoData, filterPackHalf2(a.gradient));
#if !defined(kAtrousWeights)
        sInvSum[e] = a.invSum;
#endif
        if (a.color.x != 0.0f || a.color.y != 0.0f || a.color.z != 0.0f || a.color.w != 0.0f) anyLight = 1u;
    }
    if (anyLight != 0u) sAnyLight = 1u;   // every writer writes 1
    FILTER_BARRIER();
}

#if defined(kAtrousWeights)
void atrousStore(int2 p, int2 own, float value) { CAUSTICS_IMAGE_STORE(outSums, own, float4(value, value, value, value)); }
#else
void atrousStore(int2 p, int2 own, float3 rgb, float deviation) {
#if defined(kAtrousLast)
    CAUSTICS_IMAGE_STORE(outColor, p, float4(rgb * params.invPreExposure, 1.0f));
#else
    CAUSTICS_IMAGE_STORE(outColor, own, filterNearestHalf4(float4(rgb, deviation)));
#endif
}
#endif

void atrousThread(uint group, uint local) {
    int2 tile = filterTileOf(tilesLoad(group));
    int s = params.stepWidth;
    bool region = atrousUsesRegion(s);
    int2 regionOrigin = tile * kFilterTileSize - int2(atrousApron(s), atrousApron(s));
    if (region) atrousLoadRegion(tile, regionOrigin, local);   // uniform: s is the same for the whole dispatch
    int2 p = tile * kFilterTileSize + int2(int(local % 8u), int(local / 8u));
    if (!filterInside(p, params.width, params.height)) return;
    int2 own = filterPoolTexel(group, p);   // list index = pool tile (tile_list_thread.h)
    AtrousPoint centre = atrousPoint(p, regionOrigin, region);
    bool dark = region && sAnyLight == 0u;   // every colour around is zero: so is every result
#if defined(kAtrousWeights)
    // p is the source q here.
    if (centre.id == 0u || dark) {
        atrousStore(p, own, 1.0f);
        return;
    }
    float lq = filterLuminance(centre.color.rgb), vq = centre.color.a * centre.color.a;
    float total = 0.0f;
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            int2 offset = int2(dx, dy) * s;
            AtrousPoint r = atrousPoint(p + offset, regionOrigin, region);
            if (!r.valid || r.id != centre.id) continue;
            total += atrousSpreadWeight(offset, s, centre.normalDepth.w, r.normalDepth.w, centre.gradient, centre.normalDepth.xyz,
                                        r.normalDepth.xyz, lq, filterLuminance(r.color.rgb), vq, r.color.a * r.color.a,
                                        params.sigmaLuminance);
        }
    }
    atrousStore(p, own, total);   // >= the centre's own weight 9/64 > 0
#else
    if (centre.id == 0u || dark) {
        atrousStore(p, own, centre.color.rgb, centre.color.a);
        return;
    }
    float lp = filterLuminance(centre.color.rgb), vp = centre.color.a * centre.color.a;
    float3 sum = float3(0.0f, 0.0f, 0.0f);
    float variance = 0.0f;
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            AtrousPoint q = atrousPoint(p + int2(dx, dy) * s, regionOrigin, region);
            if (!q.valid || q.id != centre.id) continue;
            float vq = q.color.a * q.color.a;
            float share = atrousSpreadWeight(int2(-dx, -dy) * s, s, q.normalDepth.w, centre.normalDepth.w, q.gradient,
                                             q.normalDepth.xyz, centre.normalDepth.xyz, filterLuminance(q.color.rgb), lp, vq,
                                             vp, params.sigmaLuminance) *
                          q.invSum;
            sum += share * q.color.rgb;
            variance += share * share * vq;
        }
    }
    atrousStore(p, own, sum, sqrt(variance));
#endif
}

#endif  // CAUSTICS_PASS_CAUSTIC_ATROUS_THREAD_H
