#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Variance of the accumulated luminance: the scale of the a-trous luminance edge-stopping (SVGF
// section 4.2; docs/caustics.md "Filter"). With 4 or more frames of history it is temporal: the
// per-frame variance E[l^2] - E[l]^2 from the accumulated moments, max(own, 3x3 mean). Shorter histories use a spatial
// estimate of the photon shot noise: a pixel's caustic radiance is a sum of photon splats, so its
// per-frame variance is about q E[l], q being the luminance one photon adds (a compound Poisson sum
// of near-equal quanta). q is the smallest non-zero luminance of this frame in the 7x7 window (a
// pixel that one photon reached), E[l] is max(own, 3x3 mean) of the accumulated luminance: a pixel that
// no photon reached inside a lit region is a draw of zero from the region's mean, so it gets that mean's
// noise and the a-trous passes fill it; with E[l] = own it had zero variance and stayed a dark hole
// (the max keeps a focal spot's own, larger, noise). SVGF's 7x7 sample
// variance would count a focal spot's own shape as noise and blur it away; shot noise grows only as
// the square root of the photon count, so a bright spot of many photons keeps its edges.
// Output (pool, pre-exposed): rgb the mean, alpha the standard deviation of the accumulated mean,
// sqrt(per-frame variance / n) (a deviation, not a variance: half precision holds its range). Over the
// listed tiles; a neighbour in a tile without a pool tile (no photon, no history kept) counts as zero in
// the 3x3 means.
layout(local_size_x = 8, local_size_y = 8) in;
#include "caustic_filter/filter_common.glsl"
layout(set = 0, binding = 0) uniform texture2D current;          // this frame, unfiltered (screen)
layout(set = 0, binding = 1) uniform texture2D temporalColor;    // pool: rgb mean, a per-frame deviation
layout(set = 0, binding = 2) uniform utexture2D temporalGuides;  // pool: n (filterPackGuide)
layout(set = 0, binding = 3) uniform utexture2D gObjectId;
layout(set = 0, binding = 4, rgba16f) uniform writeonly image2D outColor;   // pool
layout(set = 0, binding = 5, std430) readonly buffer TileList { uint tiles[]; };
layout(set = 0, binding = 6) uniform utexture2D slotMap;   // this frame's
layout(push_constant) uniform Push { int width; int height; float preExposure; } pc;

const float kTemporalHistory = 4.0;   // SVGF's threshold for trusting the temporal moments

// This frame's pool texel of screen pixel q, or (-1, -1) where its tile has none.
ivec2 poolTexel(ivec2 q) {
    uint slot = texelFetch(slotMap, q / kFilterTileSize, 0).r;
    return slot == kFilterNoSlot ? ivec2(-1) : filterPoolTexel(slot, filterLocal(q));
}

// E[l], per-frame variance, n at pool texel t (E[l] is the luminance of the mean).
vec3 momentsAt(ivec2 t) {
    vec4 c = texelFetch(temporalColor, t, 0);
    return vec3(filterLuminance(c.rgb), c.a * c.a, filterUnpackGuide(texelFetch(temporalGuides, t, 0).rg).historyLength);
}

// 3x3 mean of the neighbours' temporal variance on the same object (SVGF prefilters the variance the
// same way): a pixel's own moments from a few photons per frame estimate its variance poorly.
float localMeanTemporalVariance(ivec2 p, uint id) {
    float sum = 0.0, count = 0.0;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 q = p + ivec2(dx, dy);
            if (q.x < 0 || q.y < 0 || q.x >= pc.width || q.y >= pc.height) continue;
            if (texelFetch(gObjectId, q, 0).r != id) continue;
            ivec2 t = poolTexel(q);
            if (t.x >= 0) sum += momentsAt(t).y;
            count += 1.0;
        }
    }
    return sum / max(count, 1.0);
}

void main() {
    ivec2 p = filterTilePixel(tiles[gl_WorkGroupID.x], gl_LocalInvocationID.xy);
    if (p.x >= pc.width || p.y >= pc.height) return;
    ivec2 own = filterPoolTexel(gl_WorkGroupID.x, ivec2(gl_LocalInvocationID.xy));
    vec3 accumulated = texelFetch(temporalColor, own, 0).rgb;
    vec3 moments = momentsAt(own);
    uint id = texelFetch(gObjectId, p, 0).r;
    float n = max(moments.z, 1.0);
    float variance = 0.0;
    if (id != 0u && n >= kTemporalHistory) {
        variance = max(moments.y, localMeanTemporalVariance(p, id));
    } else if (id != 0u) {
        float quantum = 3.0e38;
        float localSum = 0.0, localCount = 0.0;
        for (int dy = -3; dy <= 3; ++dy) {
            for (int dx = -3; dx <= 3; ++dx) {
                ivec2 q = p + ivec2(dx, dy);
                if (q.x < 0 || q.y < 0 || q.x >= pc.width || q.y >= pc.height) continue;
                if (texelFetch(gObjectId, q, 0).r != id) continue;
                float l = filterLuminance(texelFetch(current, q, 0).rgb * pc.preExposure);
                if (l > 0.0) quantum = min(quantum, l);
                if (abs(dx) <= 1 && abs(dy) <= 1) {
                    ivec2 t = poolTexel(q);
                    if (t.x >= 0) localSum += filterLuminance(texelFetch(temporalColor, t, 0).rgb);
                    localCount += 1.0;
                }
            }
        }
        float expected = max(filterLuminance(accumulated), localSum / max(localCount, 1.0));
        if (quantum < 3.0e38) variance = quantum * expected;
    }
    imageStore(outColor, own, filterNearestHalf(vec4(accumulated, sqrt(variance / n))));
}
