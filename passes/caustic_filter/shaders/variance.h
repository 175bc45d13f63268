#ifndef CAUSTICS_PASS_CAUSTIC_VARIANCE_H
#define CAUSTICS_PASS_CAUSTIC_VARIANCE_H
// caustics.variance in the shared dialect (docs/shaders.md): the variance of the accumulated luminance,
// the scale of the a-trous luminance edge-stopping (SVGF section 4.2; docs/caustics.md "Variance").
// With 4 or more frames of history it is temporal: the per-frame variance E[l^2] - E[l]^2 from the
// accumulated moments, max(own, 3x3 mean). Shorter histories use a spatial estimate of the photon shot
// noise: a pixel's caustic radiance is a sum of photon splats, so its per-frame variance is about q E[l],
// q being the luminance one photon adds (a compound Poisson sum of near-equal quanta). q is the smallest
// non-zero luminance of this frame in the 7x7 window (a pixel that one photon reached), E[l] is
// max(own, 3x3 mean) of the accumulated luminance: a pixel that no photon reached inside a lit region is
// a draw of zero from the region's mean, so it gets that mean's noise and the a-trous passes fill it.
// SVGF's 7x7 sample variance would count a focal spot's own shape as noise and blur it away. The second
// type's step differs between pixels with its gather disk's area (photon weights, second_type_guides.h),
// and a pixel whose guides were filled from a neighbour's counts as one draw of the path its sample
// took (docs/caustics.md "Second-type guides").
// Output (pool, pre-exposed): rgb the mean, alpha the standard deviation of the accumulated mean,
// sqrt(per-frame variance / n). Over the listed tiles; a neighbour in a tile without a pool tile counts
// as zero in the 3x3 means. The a-trous iterations follow it (it runs only for them): it also zeroes
// each pixel's word of their first weight-sum region (caustics.atrous.sums, atrous.h), which the first
// pairs pass adds into, so that region needs no clear pass of its own. Entries: variance.comp, variance.hlsl.
#include "filter_common.h"

CAUSTICS_SHARED_BEGIN
// Push constants (variance_bindings.h), 16 bytes.
struct VarianceParams {
    int width;
    int height;
    float preExposure;   // this frame's (docs/caustics.md "Memory")
    // 1: gNormal.w holds each pixel's photon weight (the second type's guides, second_type_guides.h): one
    // photon's step in luminance differs from pixel to pixel in proportion to it.
    uint photonWeights;
};
CAUSTICS_CONST float kVarianceTemporalHistory = 4.0f;   // SVGF's threshold for trusting the temporal moments

// The deviation of the accumulated mean the a-trous passes read: per-frame variance over n frames.
CAUSTICS_FN float varianceDeviationOfMean(float perFrameVariance, float historyLength) {
    return sqrt(perFrameVariance / max(historyLength, 1.0f));
}
CAUSTICS_SHARED_END

#if !defined(CAUSTICS_LANG_CPP)
#include "bindings/caustic_variance.h"   // generated from passes/caustic_filter/variance_bindings.h
#include "common/resources.h"

// This frame's pool texel of screen pixel q, or (-1, -1) where its tile has none.
int2 variancePoolTexel(int2 q) {
    uint slot = CAUSTICS_TEXEL_UINT(slotMap, filterTileOfPixel(q));
    return slot == kFilterNoSlot ? int2(-1, -1) : filterPoolTexel(slot, q);
}

// The history length n of a pool texel (filter_common.h).
float varianceHistoryLength(int2 t) { return filterGuideLength(CAUSTICS_TEXEL(temporalGuides, t).x); }

// This frame's object id and, where the pixel has a pool texel, its temporal result's luminance and
// per-frame variance, over the group's region (filter_common.h), loaded once per group: the 3x3 means
// below read them there instead of fetching each texel up to nine times per group (docs/caustics.md
// "Cost"). A pixel without a pool texel counts as zero.
CAUSTICS_GROUPSHARED uint sVarianceId[kFilterRegion * kFilterRegion];
CAUSTICS_GROUPSHARED float sVarianceLuminance[kFilterRegion * kFilterRegion];
CAUSTICS_GROUPSHARED float sVarianceVariance[kFilterRegion * kFilterRegion];

// List order (common/specular_list.h): the index texels of the 3x3 tiles around the group's, which hold
// every pixel the region and the shot-noise window (3 pixels around a pixel of the tile) read, so that a
// lookup reads group-shared memory instead of a dependent texel fetch (docs/caustics.md "Second-type memory").
CAUSTICS_GROUPSHARED uint4 sVarianceIndex[9];

// Pixel q's input texel (SPECULAR_INPUT_TEXEL) for q in the view within 3 pixels of the group's tile.
int2 varianceInputTexel(int2 q, int2 origin) {
    if (FILTER_LIST_ORDER_ON == 0u) return q;
    int2 t = int2(q.x >> kFilterTileShift, q.y >> kFilterTileShift) - int2(origin.x >> kFilterTileShift, origin.y >> kFilterTileShift);
    return specularListTexel(specularListEntry(sVarianceIndex[(t.y + 1) * 3 + t.x + 1], q));
}

// Fills the region (id 0 outside the view), after the index cache; every thread of the group calls it
// (two barriers).
void varianceLoadRegion(int2 origin, uint local) {
    if (FILTER_LIST_ORDER_ON != 0u) {   // per pipeline: the barrier is reached by the whole group or by none of it
        if (local < 9u) {
            int2 tile = int2(origin.x >> kFilterTileShift, origin.y >> kFilterTileShift) + int2(int(local % 3u) - 1, int(local / 3u) - 1);
            int2 tiles = int2((params.width + kFilterTileSize - 1) >> kFilterTileShift, (params.height + kFilterTileSize - 1) >> kFilterTileShift);
            sVarianceIndex[local] = filterInside(tile, tiles.x, tiles.y) ? CAUSTICS_TEXEL(specularIndex, tile) : uint4(0u, 0u, 0u, 0u);
        }
        CAUSTICS_GROUP_BARRIER();
    }
    for (uint i = local; i < uint(kFilterRegion * kFilterRegion); i += kFilterGroupThreads) {
        int2 q = filterRegionPixel(i, origin);
        bool inside = filterInside(q, params.width, params.height);
        int2 t = inside ? variancePoolTexel(q) : int2(-1, -1);
        float4 c = t.x >= 0 ? CAUSTICS_TEXEL(temporalColor, t) : float4(0.0f, 0.0f, 0.0f, 0.0f);
        sVarianceId[i] = FILTER_INPUT_UINT(gObjectId, inside ? varianceInputTexel(q, origin) : int2(-1, -1));
        sVarianceLuminance[i] = filterLuminance(c.rgb);
        sVarianceVariance[i] = c.a * c.a;
    }
    CAUSTICS_GROUP_BARRIER();
}

// 3x3 mean of the neighbours' temporal variance on the same object (SVGF prefilters the variance the
// same way): a pixel's own moments from a few photons per frame estimate its variance poorly.
float varianceLocalMeanTemporal(int2 p, int2 origin, uint id) {
    float sum = 0.0f, count = 0.0f;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            int2 q = p + int2(dx, dy);
            int r = filterRegionIndex(q, origin);
            if (!filterInside(q, params.width, params.height) || sVarianceId[r] != id) continue;
            sum += sVarianceVariance[r];
            count += 1.0f;
        }
    }
    return sum / max(count, 1.0f);
}

// A pixel's photon weight (VarianceParams::photonWeights), 1 where the pixels share one step; negative
// where the pixel's guides were filled from a neighbour's (second_type_guide_fill.h): its sample took
// another path, whose luminance says nothing about this receiver's step.
// t: the pixel's input texel (SPECULAR_INPUT_TEXEL), on a listed pixel.
float variancePhotonWeight(int2 t) { return params.photonWeights != 0u ? FILTER_INPUT(gNormal, t).w : 1.0f; }

// Photon shot noise q E[l] for a short history (above). With photon weights w (the second type through
// curved glass) the step is w_p times the smallest per-weight luminance l / w of the window.
float varianceShotNoise(int2 p, int2 origin, uint id, float accumulatedLuminance) {
    float quantum = 3.0e38f;
    float localSum = 0.0f, localCount = 0.0f;
    for (int dy = -3; dy <= 3; ++dy) {
        for (int dx = -3; dx <= 3; ++dx) {
            int2 q = p + int2(dx, dy);
            if (!filterInside(q, params.width, params.height)) continue;
            int2 t = varianceInputTexel(q, origin);
            if (FILTER_INPUT_UINT(gObjectId, t) != id) continue;
            float l = filterLuminance(FILTER_INPUT(current, t).rgb * params.preExposure);
            float w = variancePhotonWeight(t);
            if (l > 0.0f && w > 0.0f) quantum = min(quantum, l / w);
            if (abs(dx) <= 1 && abs(dy) <= 1) {
                localSum += sVarianceLuminance[filterRegionIndex(q, origin)];
                localCount += 1.0f;
            }
        }
    }
    float expected = max(accumulatedLuminance, localSum / max(localCount, 1.0f));
    // A filled pixel's value is one draw of which path its sample took (zero where it left the scene):
    // its deviation is of the order of the mean itself, not of one photon's step.
    float ownWeight = variancePhotonWeight(varianceInputTexel(p, origin));
    if (ownWeight < 0.0f) return expected * expected;
    return quantum < 3.0e38f ? quantum * ownWeight * expected : 0.0f;
}

void varianceThread(uint group, uint2 local) {
    int2 origin = filterTileOf(tilesLoad(group)) * kFilterTileSize;
    int2 p = origin + int2(local);
    varianceLoadRegion(origin, local.y * uint(kFilterTileSize) + local.x);
    if (!filterInside(p, params.width, params.height)) return;
    // Every word the first pairs pass adds into or its shares pass reads is a listed pixel's in the view.
    weightSumsStore(filterPoolWord(0u, group, p), 0u);
    int2 own = filterPoolTexel(group, p);
    float4 c = CAUSTICS_TEXEL(temporalColor, own);
    float n = max(varianceHistoryLength(own), 1.0f);
    uint id = FILTER_INPUT_UINT(gObjectId, varianceInputTexel(p, origin));
    float variance = 0.0f;
    if (id != 0u && n >= kVarianceTemporalHistory) variance = max(c.a * c.a, varianceLocalMeanTemporal(p, origin, id));
    else if (id != 0u) variance = varianceShotNoise(p, origin, id, filterLuminance(c.rgb));
    CAUSTICS_IMAGE_STORE(outColor, own, filterNearestHalf4(float4(c.rgb, varianceDeviationOfMean(variance, n))));
}
#endif

#endif  // CAUSTICS_PASS_CAUSTIC_VARIANCE_H
