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

// The guides packed once per frame by caustics.temporal (mirror of filter_common.glsl): x linear depth
// bits, y its gradient (2 x half), z the octahedral normal (2 x snorm16, x in the low half), w object id.
struct FilterGuide {
    float depth;
    float2 gradZ;
    float3 normal;
    uint id;
};
uint filterPackSnorm2x16(float2 v) {
    int2 q = int2(round(clamp(v, -1.0f, 1.0f) * 32767.0f));
    return (uint(q.x) & 0xFFFFu) | (uint(q.y) << 16);
}
float2 filterUnpackSnorm2x16(uint bits) {
    int2 q = int2(int(bits << 16) >> 16, int(bits) >> 16);
    return clamp(float2(q) / 32767.0f, -1.0f, 1.0f);
}
uint4 filterPackGuide(float depth, float2 gradZ, float3 n, uint id) {
    float l1 = abs(n.x) + abs(n.y) + abs(n.z);
    n = l1 > 0.0f ? n / l1 : float3(0.0f, 0.0f, 1.0f);
    float2 e = n.z >= 0.0f ? n.xy : (1.0f - abs(n.yx)) * float2(n.x >= 0.0f ? 1.0f : -1.0f, n.y >= 0.0f ? 1.0f : -1.0f);
    return uint4(asuint(depth), f32tof16(gradZ.x) | (f32tof16(gradZ.y) << 16), filterPackSnorm2x16(e), id);
}
FilterGuide filterUnpackGuide(uint4 g) {
    float2 e = filterUnpackSnorm2x16(g.z);
    float3 n = float3(e, 1.0f - abs(e.x) - abs(e.y));
    float t = max(-n.z, 0.0f);
    n.xy += float2(n.x >= 0.0f ? -t : t, n.y >= 0.0f ? -t : t);
    FilterGuide r;
    r.depth = asfloat(g.x);
    r.gradZ = float2(f16tof32(g.y & 0xFFFFu), f16tof32(g.y >> 16));
    r.normal = normalize(n);
    r.id = g.w;
    return r;
}

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
