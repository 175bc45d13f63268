#ifndef CAUSTICS_CAUSTIC_FILTER_COMMON_GLSL
#define CAUSTICS_CAUSTIC_FILTER_COMMON_GLSL
// Helpers shared by the caustic filter's compute shaders (docs/caustics.md, "Filter"); HLSL twin in
// shaders/d3d12/caustic_filter/filter_common.hlsli.

// Rec. 709 luminance: the scalar whose moments and differences guide the filter (SVGF section 4.2).
float filterLuminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

// The filter runs over 8x8 pixel tiles (docs/caustics.md "Filter", "Tiles"): tiles.comp lists the tiles
// that received photons (and their neighbours) or still hold history, packed x | y << 16, and every filter pass is dispatched
// indirectly, one 8x8 group per listed tile. No filter pass writes a pixel of an unlisted tile, so its
// texels of the filter's textures are undefined this frame: neighbourhood reads skip such pixels.
const int kFilterTileSize = 8;
// Tile state (tiles.comp): frames the tile's history is kept (0: not listed, its texels stale), bit 31
// set when a photon reached the tile this frame.
const uint kFilterTilePhotons = 0x80000000u, kFilterTileKeepMask = 0x7FFFFFFFu;
ivec2 filterTilePixel(uint tile, uvec2 texel) {
    return ivec2(int(tile & 0xFFFFu), int(tile >> 16)) * kFilterTileSize + ivec2(texel);
}

// Where the filter keeps its per-pixel data (docs/caustics.md "Filter", "Memory"): not in full-screen
// images but in a pool of 8x8 tiles, one per listed tile. The tile at index i of this frame's list
// (tile_list.comp) owns pool tile i; a per-screen-tile slot map (R32UI) names the pool tile of every
// screen tile, kFilterNoSlot where none (not listed, or listed past the pool's capacity). The pool is an
// image kFilterPoolTilesPerRow tiles wide. Last frame's history is found through last frame's map.
const uint kFilterNoSlot = 0xFFFFFFFFu;
const uint kFilterPoolTilesPerRow = 128u;
ivec2 filterPoolTexel(uint slot, ivec2 local) {
    return ivec2(int(slot % kFilterPoolTilesPerRow), int(slot / kFilterPoolTilesPerRow)) * kFilterTileSize + local;
}
ivec2 filterLocal(ivec2 p) { return p - (p / kFilterTileSize) * kFilterTileSize; }

// The history guides, one RG32UI texel (docs/caustics.md "Filter", "History"): x the linear depth and
// the history length n (2 x half: 11 significant bits, exact integers up to 2048 > kMaxFilterHistory),
// y the octahedral normal (2 x unorm8) and the object id's low 16 bits. Only the next frame's
// disocclusion test reads them (1 % depth tolerance, a normal cosine of 0.9, id equality); this
// frame's a-trous passes read the G-buffer itself at full precision.
struct FilterGuide {
    float depth;
    float historyLength;
    vec3 normal;
    uint id;   // low 16 bits
};
uvec2 filterPackGuide(float depth, float historyLength, vec3 n, uint id) {
    float l1 = abs(n.x) + abs(n.y) + abs(n.z);
    n = l1 > 0.0 ? n / l1 : vec3(0.0, 0.0, 1.0);
    vec2 e = n.z >= 0.0 ? n.xy : (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
    uvec2 q = uvec2(round(clamp(e * 0.5 + 0.5, 0.0, 1.0) * 255.0));
    return uvec2(packHalf2x16(vec2(depth, historyLength)), q.x | (q.y << 8) | ((id & 0xFFFFu) << 16));
}
FilterGuide filterUnpackGuide(uvec2 g) {
    vec2 dn = unpackHalf2x16(g.x);
    vec2 e = vec2(float(g.y & 0xFFu), float((g.y >> 8) & 0xFFu)) / 255.0 * 2.0 - 1.0;
    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    float t = max(-n.z, 0.0);
    n.xy += vec2(n.x >= 0.0 ? -t : t, n.y >= 0.0 ? -t : t);
    return FilterGuide(dn.x, dn.y, normalize(n), g.y >> 16);
}
uint filterGuideId(uint objectId) { return objectId & 0xFFFFu; }

// v rounded to the nearest half-precision value, to be written into an RGBA16F pool image: Vulkan lets
// the image write round towards zero (lavapipe does), which biased every store low by half an ulp on
// average (0.11 % of the energy after three stores, docs/caustics.md "Memory"); a value that half
// represents exactly is written exactly under any rounding. In 32-bit arithmetic: the mantissa rounded
// to half's 10 bits (to nearest, ties to even), below half's smallest normal to multiples of 2^-24.
float filterNearestHalf(float v) {
    if (abs(v) < 6.103515625e-5) return round(v * 16777216.0) / 16777216.0;
    uint u = floatBitsToUint(v);
    return uintBitsToFloat((u + 0xFFFu + ((u >> 13) & 1u)) & ~0x1FFFu);
}
vec4 filterNearestHalf(vec4 v) {
    return vec4(filterNearestHalf(v.x), filterNearestHalf(v.y), filterNearestHalf(v.z), filterNearestHalf(v.w));
}

// B3-spline a-trous kernel taps for |offset| = 0, 1, 2 (1/16 (1 4 6 4 1)).
const float kFilterKernel[3] = float[](3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0);

// Relative linear-depth tolerance for a reprojected history tap up to one pixel away: 1 % plus the
// depth change across two pixel footprints on a surface seen at the given angle (the same footprint
// argument as the first-type splat's depth test, docs/caustics.md "Forward trace").
float filterRelativeDepthTolerance(float tanHalfFovY, float imageHeight, vec3 normal, vec3 toEye) {
    float cosView = max(abs(dot(normal, toEye)), 0.05);
    float tanView = sqrt(max(0.0, 1.0 - cosView * cosView)) / cosView;
    return 0.01 + 2.0 * (2.0 * tanHalfFovY / imageHeight) * tanView;
}

// Weight with which source pixel q spreads its radiance to pixel p = q + offset in one a-trous
// iteration (SVGF's edge-stopping functions, Schied et al. 2017, eq. 3-5, with a Gaussian luminance term):
//   w_z = exp(-|z_p - z_q - grad z_q . offset| / (|grad z_q . offset| + 0.002 z_q step))   (a plane passes)
//   w_n = max(0, n_q . n_p)^128
//   w_l = exp(-d^2 / 2),  d = |l_p - l_q| / (sigma_l sqrt(Var_q + Var_p))
// times the B3 kernel; the caller checks the object id. The luminance term uses the variance of the
// difference, so it is symmetric in p and q: no net flow between two pixels whose difference is noise
// (a one-sided scale drains a focal spot's shoulders into the darker plateau around it). Gaussian, not
// SVGF's exp(-d): a difference of one deviation keeps 0.61 of the weight (noise is averaged), one of
// three keeps 0.011 (a fold line or a cusp stops the spreading); exp(-d) keeps 0.37 and 0.05, which
// blurred the ring's cusp to 0.82 of its peak in one frame (docs/caustics.md "Filter").
float filterSpreadWeight(ivec2 offset, int stepWidth, float zq, float zp, vec2 gradZq, vec3 nq, vec3 np, float lq,
                         float lp, float varianceQ, float varianceP, float sigmaLuminance) {
    ivec2 k = abs(offset) / stepWidth;
    float planar = dot(gradZq, vec2(offset));
    float wz = exp(-abs(zp - zq - planar) / (abs(planar) + 0.002 * zq * float(stepWidth)));
    float wn = pow(max(0.0, dot(nq, np)), 128.0);
    float d = abs(lp - lq) / (sigmaLuminance * sqrt(varianceQ + varianceP) + 1e-20);
    float wl = exp(-0.5 * d * d);
    return kFilterKernel[k.x] * kFilterKernel[k.y] * wz * wn * wl;
}

#endif
