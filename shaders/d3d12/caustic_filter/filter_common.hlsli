#ifndef CAUSTICS_CAUSTIC_FILTER_COMMON_HLSLI
#define CAUSTICS_CAUSTIC_FILTER_COMMON_HLSLI
// Helpers shared by the caustic filter's compute shaders (mirror of shaders/vulkan/caustic_filter/
// filter_common.glsl; docs/caustics.md, "Filter").

// Rec. 709 luminance: the scalar whose moments and differences guide the filter (SVGF section 4.2).
float filterLuminance(float3 c) { return dot(c, float3(0.2126f, 0.7152f, 0.0722f)); }

// The filter runs over 8x8 pixel tiles (docs/caustics.md "Filter", "Tiles"): tiles.comp lists the tiles
// that received photons (and their neighbours) or still hold history, packed x | y << 16, and every filter pass is dispatched
// indirectly, one 8x8 group per listed tile. Neighbourhood reads skip pixels of unlisted tiles.
static const int kFilterTileSize = 8;
// Tile state (tiles.comp): frames the tile's history is kept (0: not listed), bit 31: photons this frame.
static const uint kFilterTilePhotons = 0x80000000u;
static const uint kFilterTileKeepMask = 0x7FFFFFFFu;
int2 filterTilePixel(uint tile, uint2 texel) {
    return int2(int(tile & 0xFFFFu), int(tile >> 16)) * kFilterTileSize + int2(texel);
}

// The filter's pool (mirror of filter_common.glsl, "pool"): listed tile i owns pool tile i; the slot
// map names each screen tile's pool tile (kFilterNoSlot: none); kFilterPoolTilesPerRow tiles to a row.
static const uint kFilterNoSlot = 0xFFFFFFFFu;
static const uint kFilterPoolTilesPerRow = 128u;
int2 filterPoolTexel(uint slot, int2 local) {
    return int2(int(slot % kFilterPoolTilesPerRow), int(slot / kFilterPoolTilesPerRow)) * kFilterTileSize + local;
}
int2 filterLocal(int2 p) { return p - (p / kFilterTileSize) * kFilterTileSize; }

// The history guides, one RG32UI texel (mirror of filter_common.glsl): x half depth | half n << 16,
// y octahedral normal (2 x unorm8) | the object id's low 16 bits << 16.
struct FilterGuide {
    float depth;
    float historyLength;
    float3 normal;
    uint id;   // low 16 bits
};
uint2 filterPackGuide(float depth, float historyLength, float3 n, uint id) {
    float l1 = abs(n.x) + abs(n.y) + abs(n.z);
    n = l1 > 0.0f ? n / l1 : float3(0.0f, 0.0f, 1.0f);
    float2 e = n.z >= 0.0f ? n.xy : (1.0f - abs(n.yx)) * float2(n.x >= 0.0f ? 1.0f : -1.0f, n.y >= 0.0f ? 1.0f : -1.0f);
    uint2 q = uint2(round(saturate(e * 0.5f + 0.5f) * 255.0f));
    return uint2(f32tof16(depth) | (f32tof16(historyLength) << 16), q.x | (q.y << 8) | ((id & 0xFFFFu) << 16));
}
FilterGuide filterUnpackGuide(uint2 g) {
    float2 e = float2(float(g.y & 0xFFu), float((g.y >> 8) & 0xFFu)) / 255.0f * 2.0f - 1.0f;
    float3 n = float3(e, 1.0f - abs(e.x) - abs(e.y));
    float t = max(-n.z, 0.0f);
    n.xy += float2(n.x >= 0.0f ? -t : t, n.y >= 0.0f ? -t : t);
    FilterGuide r;
    r.depth = f16tof32(g.x & 0xFFFFu);
    r.historyLength = f16tof32(g.x >> 16);
    r.normal = normalize(n);
    r.id = g.y >> 16;
    return r;
}
uint filterGuideId(uint objectId) { return objectId & 0xFFFFu; }

// v rounded to the nearest half, for the RGBA16F pool images (filter_common.glsl says why and how).
float filterNearestHalf(float v) {
    if (abs(v) < 6.103515625e-5f) return round(v * 16777216.0f) / 16777216.0f;
    uint u = asuint(v);
    return asfloat((u + 0xFFFu + ((u >> 13) & 1u)) & ~0x1FFFu);
}
float4 filterNearestHalf(float4 v) {
    return float4(filterNearestHalf(v.x), filterNearestHalf(v.y), filterNearestHalf(v.z), filterNearestHalf(v.w));
}
float2 filterUnpackHalf2(uint bits) { return float2(f16tof32(bits & 0xFFFFu), f16tof32(bits >> 16)); }
uint filterPackHalf2(float2 v) { return f32tof16(v.x) | (f32tof16(v.y) << 16); }

// B3-spline a-trous kernel taps for |offset| = 0, 1, 2 (1/16 (1 4 6 4 1)).
static const float kFilterKernel[3] = {3.0f / 8.0f, 1.0f / 4.0f, 1.0f / 16.0f};

// Relative linear-depth tolerance for a reprojected history tap up to one pixel away: 1 % plus the
// depth change across two pixel footprints on a surface seen at the given angle.
float filterRelativeDepthTolerance(float tanHalfFovY, float imageHeight, float3 normal, float3 toEye) {
    float cosView = max(abs(dot(normal, toEye)), 0.05f);
    float tanView = sqrt(max(0.0f, 1.0f - cosView * cosView)) / cosView;
    return 0.01f + 2.0f * (2.0f * tanHalfFovY / imageHeight) * tanView;
}

// Weight with which source pixel q spreads its radiance to pixel p = q + offset in one a-trous
// iteration (SVGF's edge-stopping functions with a Gaussian luminance term; the formulas, why the
// luminance term uses Var_q + Var_p and why it is Gaussian are in filter_common.glsl).
float filterSpreadWeight(int2 offset, int stepWidth, float zq, float zp, float2 gradZq, float3 nq, float3 np,
                         float lq, float lp, float varianceQ, float varianceP, float sigmaLuminance) {
    int2 k = abs(offset) / stepWidth;
    float planar = dot(gradZq, float2(offset));
    float wz = exp(-abs(zp - zq - planar) / (abs(planar) + 0.002f * zq * float(stepWidth)));
    float wn = pow(max(0.0f, dot(nq, np)), 128.0f);
    float d = abs(lp - lq) / (sigmaLuminance * sqrt(varianceQ + varianceP) + 1e-20f);
    float wl = exp(-0.5f * d * d);
    return kFilterKernel[k.x] * kFilterKernel[k.y] * wz * wn * wl;
}

#endif
