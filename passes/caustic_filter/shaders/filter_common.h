#ifndef CAUSTICS_PASS_CAUSTIC_FILTER_COMMON_H
#define CAUSTICS_PASS_CAUSTIC_FILTER_COMMON_H
// What the caustic filter's shared-dialect bodies share (docs/shaders.md; docs/caustics.md "Filter",
// "Tiles", "Memory"): the tiles, the pool, luminance; and, GLSL and HLSL only, the bit casts, the
// rounding to half; group-shared memory is spelled in common/group_shared.h.
#include "common/lang.h"
#include "common/luminance.h"
#include "common/specular_list.h"

CAUSTICS_SHARED_BEGIN
// The filter runs over 8x8 pixel tiles, one 8x8 group (64 threads) per listed tile (the list of
// caustics.filterTiles.list, tiles.h), packed x | y << 16. Its per-pixel data lives in a pool of 8x8 tiles, kFilterPoolTilesPerRow to a row
// (caustic_filter.h); the slot map names each screen tile's pool tile, kFilterNoSlot where none.
CAUSTICS_CONST int kFilterTileSize = 8;
CAUSTICS_CONST int kFilterTileShift = 3;        // log2 kFilterTileSize
CAUSTICS_CONST uint kFilterGroupThreads = 64u;
CAUSTICS_CONST uint kFilterNoSlot = 0xFFFFFFFFu;
CAUSTICS_CONST uint kFilterPoolTilesPerRow = 128u;
CAUSTICS_CONST uint kFilterPoolRowShift = 7u;   // log2 kFilterPoolTilesPerRow

CAUSTICS_FN int2 filterTileOf(uint packed) { return int2(int(packed & 0xFFFFu), int(packed >> 16)); }
// The screen tile of pixel p (p >= 0). Shifts and masks, not / and %: the a-trous passes find 50 taps'
// pool texels per pixel and iteration, and signed division costs several instructions.
CAUSTICS_FN int2 filterTileOfPixel(int2 p) { return int2(p.x >> kFilterTileShift, p.y >> kFilterTileShift); }
// The pool texel of screen pixel p (p >= 0) whose tile has pool tile `slot`.
CAUSTICS_FN int2 filterPoolTexel(uint slot, int2 p) {
    int2 local = int2(p.x & (kFilterTileSize - 1), p.y & (kFilterTileSize - 1));
    int2 tile = int2(int(slot & (kFilterPoolTilesPerRow - 1u)), int(slot >> kFilterPoolRowShift));
    return int2(tile.x << kFilterTileShift, tile.y << kFilterTileShift) + local;
}
// p inside a width x height view: a negative coordinate wraps to a large unsigned one.
// Pixel p's word in a per-pool-texel buffer region starting at `base` (caustics.atrous.sums): its pool
// tile's kFilterGroupThreads words, row by row.
CAUSTICS_FN uint filterPoolWord(uint base, uint slot, int2 p) {
    return base + slot * kFilterGroupThreads + uint((p.y & (kFilterTileSize - 1)) * kFilterTileSize + (p.x & (kFilterTileSize - 1)));
}

CAUSTICS_FN bool filterInside(int2 p, int width, int height) { return uint(p.x) < uint(width) && uint(p.y) < uint(height); }

// A group's tile and a one-pixel apron, kFilterRegion^2 pixels: caustics.temporal and caustics.variance
// copy what their 3x3 neighbourhoods read of it into group-shared memory once per group
// (docs/caustics.md "Cost"). `origin` is the tile's first pixel; pixel q lies within one pixel of the tile.
CAUSTICS_CONST int kFilterRegion = kFilterTileSize + 2;
CAUSTICS_FN int filterRegionIndex(int2 q, int2 origin) { return (q.y - origin.y + 1) * kFilterRegion + (q.x - origin.x + 1); }
CAUSTICS_FN int2 filterRegionPixel(uint i, int2 origin) {
    return origin - int2(1, 1) + int2(int(i) % kFilterRegion, int(i) / kFilterRegion);
}

// The scalar whose moments and differences guide the filter (SVGF section 4.2): common/luminance.h.
CAUSTICS_FN float filterLuminance(float3 c) { return rec709Luminance(c); }
CAUSTICS_SHARED_END

#if !defined(CAUSTICS_LANG_CPP)
#include "common/group_shared.h"
#if defined(CAUSTICS_LANG_HLSL)
float2 filterUnpackHalf2(uint u) { return float2(f16tof32(u & 0xFFFFu), f16tof32(u >> 16)); }
uint filterPackHalf2(float2 v) { return f32tof16(v.x) | (f32tof16(v.y) << 16); }
float filterBitsToFloat(uint u) { return asfloat(u); }
uint filterFloatToBits(float v) { return asuint(v); }
#else
float2 filterUnpackHalf2(uint u) { return unpackHalf2x16(u); }
uint filterPackHalf2(float2 v) { return packHalf2x16(v); }
float filterBitsToFloat(uint u) { return uintBitsToFloat(u); }
uint filterFloatToBits(float v) { return floatBitsToUint(v); }
#endif

// The history length n from a history guide's first word (filterPackGuide, temporal_thread.h): the high
// half, negative while a rise is pending (temporal.h, temporalVerdict).
float filterGuideLength(uint x) { return abs(filterUnpackHalf2(x).y); }

// The frame inputs' layout, fixed per pipeline (common/specular_list.h): the *_list entries define
// FILTER_LIST_ORDER for the second type's run in list order, so the merged default's code has no
// list-order branch (docs/caustics.md "Second-type memory").
#if defined(FILTER_LIST_ORDER)
#define FILTER_LIST_ORDER_ON 1u
#else
#define FILTER_LIST_ORDER_ON 0u
#endif

// A frame input's texel t (the pixel itself, or its list entry's texel: SPECULAR_INPUT_TEXEL,
// common/specular_list.h), zero where t is (-1, -1): a pixel the second type's list leaves out.
#define FILTER_INPUT(tex, t) ((t).x >= 0 ? CAUSTICS_TEXEL(tex, (t)) : float4(0.0f, 0.0f, 0.0f, 0.0f))
#define FILTER_INPUT_UINT(tex, t) ((t).x >= 0 ? CAUSTICS_TEXEL_UINT(tex, (t)) : 0u)

// v rounded to the nearest half-precision value, to be written into an RGBA16F pool image: Vulkan lets
// the image write round towards zero (lavapipe does), which biased every store low by half an ulp on
// average (docs/caustics.md "Memory"); a value half represents exactly is written exactly under any
// rounding. In 32-bit arithmetic: the mantissa rounded to half's 10 bits (to nearest, ties to even),
// below half's smallest normal to multiples of 2^-24.
float filterNearestHalf(float v) {
    if (abs(v) < 6.103515625e-5f) return round(v * 16777216.0f) / 16777216.0f;
    uint u = filterFloatToBits(v);
    return filterBitsToFloat((u + 0xFFFu + ((u >> 13) & 1u)) & ~0x1FFFu);
}
float4 filterNearestHalf4(float4 v) {
    return float4(filterNearestHalf(v.x), filterNearestHalf(v.y), filterNearestHalf(v.z), filterNearestHalf(v.w));
}
#endif

#endif  // CAUSTICS_PASS_CAUSTIC_FILTER_COMMON_H
