#ifndef CAUSTICS_PASS_CAUSTIC_ATROUS_THREAD_H
#define CAUSTICS_PASS_CAUSTIC_ATROUS_THREAD_H
// The thread function of caustics.atrous.N.weights (kAtrousWeights) and caustics.atrous.N (GLSL and
// HLSL; the pure functions are atrous.h). One 8x8 group per listed tile (the group index is the tile's
// pool tile); each tap is fetched through this frame's slot map (a group-shared region of the tile and
// its apron measured 3-4x slower on the H200: docs/caustics.md "Cost"):
//   weights  W_q of the group's pixels, the sum of their weights to the 5x5 receivers that hold data;
//            a source without light writes 1 (it hands out nothing, whatever divides it);
//   shares   each pixel receives w(q -> p) / W_q of its 5x5 sources, the dark ones skipped after one
//            colour fetch (or, kAtrousLast, writes caustics.radiance).
// A pixel outside the view or in a tile without a pool tile holds nothing: it is neither a source nor a
// receiver (docs/caustics.md "Tiles": the energy stays in the listed tiles).
#if defined(kAtrousWeights)
#include "bindings/caustic_atrous_weights.h"   // generated from passes/caustic_filter/atrous_bindings.h
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

// A pixel's guide (filterPackAtrousGuide, caustics.temporal): normal, linear depth, id, depth slope.
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

// The pool texel of screen pixel p, or (-1, -1) where p is outside the view or its tile has no pool tile.
int2 atrousPoolTexel(int2 p) {
    if (!filterInside(p, params.width, params.height)) return int2(-1, -1);
    uint slot = CAUSTICS_TEXEL_UINT(slotMap, filterTileOfPixel(p));
    return slot == kFilterNoSlot ? int2(-1, -1) : filterPoolTexel(slot, p);
}

bool atrousIsDark(float4 c) { return c.x == 0.0f && c.y == 0.0f && c.z == 0.0f && c.w == 0.0f; }

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
    int s = params.stepWidth;
    int2 p = filterTileOf(tilesLoad(group)) * kFilterTileSize + int2(int(local % 8u), int(local / 8u));
    if (!filterInside(p, params.width, params.height)) return;
    int2 own = filterPoolTexel(group, p);   // list index = pool tile (tile_list_thread.h)
    float4 centreColor = CAUSTICS_TEXEL(inColor, own);
#if defined(kAtrousWeights)
    // p is the source q here. A source without light hands out nothing: its W_q divides zero.
    if (atrousIsDark(centreColor)) {
        atrousStore(p, own, 1.0f);
        return;
    }
    AtrousGuide centre = atrousGuide(own);
    if (centre.id == 0u) {
        atrousStore(p, own, 1.0f);
        return;
    }
    float lq = filterLuminance(centreColor.rgb), vq = centreColor.a * centreColor.a;
    float total = 0.0f;
    ATROUS_UNROLL for (int dy = -2; dy <= 2; ++dy) {
        ATROUS_UNROLL for (int dx = -2; dx <= 2; ++dx) {
            int2 t = atrousPoolTexel(p + int2(dx, dy) * s);
            if (t.x < 0) continue;
            AtrousGuide r = atrousGuide(t);
            if (r.id != centre.id) continue;
            float4 c = CAUSTICS_TEXEL(inColor, t);
            total += atrousSpreadWeight(int2(dx, dy), s, centre.depth, r.depth, centre.gradient, centre.normal, r.normal, lq,
                                        filterLuminance(c.rgb), vq, c.a * c.a, params.sigmaLuminance, params.depthJitter);
        }
    }
    atrousStore(p, own, total);   // >= the centre's own weight 9/64 > 0
#else
    AtrousGuide centre = atrousGuide(own);
    if (centre.id == 0u) {
        atrousStore(p, own, centreColor.rgb, centreColor.a);
        return;
    }
    float lp = filterLuminance(centreColor.rgb), vp = centreColor.a * centreColor.a;
    float3 sum = float3(0.0f, 0.0f, 0.0f);
    float variance = 0.0f;
    ATROUS_UNROLL for (int dy = -2; dy <= 2; ++dy) {
        ATROUS_UNROLL for (int dx = -2; dx <= 2; ++dx) {
            int2 t = atrousPoolTexel(p + int2(dx, dy) * s);
            if (t.x < 0) continue;
            float4 c = CAUSTICS_TEXEL(inColor, t);
            if (atrousIsDark(c)) continue;   // a dark source gives nothing: no guide, no weight
            AtrousGuide q = atrousGuide(t);
            if (q.id != centre.id) continue;
            float vq = c.a * c.a;
            float share = atrousSpreadWeight(int2(-dx, -dy), s, q.depth, centre.depth, q.gradient, q.normal, centre.normal,
                                             filterLuminance(c.rgb), lp, vq, vp, params.sigmaLuminance, params.depthJitter) /
                          CAUSTICS_TEXEL(sums, t).x;
            sum += share * c.rgb;
            variance += share * share * vq;
        }
    }
    atrousStore(p, own, sum, sqrt(variance));
#endif
}

#endif  // CAUSTICS_PASS_CAUSTIC_ATROUS_THREAD_H
