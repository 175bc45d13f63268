#ifndef CAUSTICS_PASS_CAUSTIC_TEMPORAL_THREAD_H
#define CAUSTICS_PASS_CAUSTIC_TEMPORAL_THREAD_H
// caustics.temporal's thread function (GLSL and HLSL; temporal.h says what it computes) and the two
// guides it packs.
// The entry includes the camera's struct first (scene/camera.glsl or .hlsli: it has matrices, so it is
// not in the shared dialect; the HLSL embedder inlines every include, whatever the #if around it).
#include "bindings/caustic_temporal.h"   // generated from passes/caustic_filter/temporal_bindings.h
#include "common/caster_motion.h"
#include "common/octahedral.h"
#include "common/resources.h"

// The rejection test's 3x3 loops unrolled (the GLSL entry enables GL_EXT_control_flow_attributes).
#if defined(CAUSTICS_LANG_HLSL)
#define TEMPORAL_UNROLL [unroll]
#else
#define TEMPORAL_UNROLL [[unroll]]
#endif

// The history guides, one RG32UI texel (docs/caustics.md "History and guides"): x the linear depth and
// the history length n (2 x half: 11 significant bits, exact integers up to 2048 > kMaxFilterHistory;
// negative while a rise is pending, temporalVerdict), y the octahedral normal (2 x unorm8) and the
// object id's low 16 bits. Only the next frame's disocclusion test reads them (1 % depth tolerance, a
// normal cosine of 0.9, id equality) and this frame's variance and output passes the length
// (filterGuideLength).
struct FilterGuide {
    float depth;
    float historyLength;
    bool risePending;
    float3 normal;
    uint id;   // low 16 bits
};
uint2 filterPackGuide(float depth, float historyLength, bool risePending, float3 n, uint id) {
    historyLength = risePending ? -historyLength : historyLength;
    float l1 = abs(n.x) + abs(n.y) + abs(n.z);
    n = l1 > 0.0f ? n / l1 : float3(0.0f, 0.0f, 1.0f);
    float2 e = n.z >= 0.0f ? n.xy
                           : (float2(1.0f, 1.0f) - abs(n.yx)) * float2(n.x >= 0.0f ? 1.0f : -1.0f, n.y >= 0.0f ? 1.0f : -1.0f);
    uint2 q = uint2(round(clamp(e * 0.5f + 0.5f, 0.0f, 1.0f) * 255.0f));
    return uint2(filterPackHalf2(float2(depth, historyLength)), q.x | (q.y << 8) | ((id & 0xFFFFu) << 16));
}
// The object id's low 16 bits a packed guide holds (the rejection test reads only it, with the length).
uint filterGuideStoredId(uint2 g) { return g.y >> 16; }
FilterGuide filterUnpackGuide(uint2 g) {
    float2 dn = filterUnpackHalf2(g.x);
    float2 e = float2(float(g.y & 0xFFu), float((g.y >> 8) & 0xFFu)) / 255.0f * 2.0f - 1.0f;
    float3 n = float3(e.x, e.y, 1.0f - abs(e.x) - abs(e.y));
    float t = max(-n.z, 0.0f);
    n.xy += float2(n.x >= 0.0f ? -t : t, n.y >= 0.0f ? -t : t);
    FilterGuide r;
    r.depth = dn.x;
    r.historyLength = filterGuideLength(g.x);
    r.risePending = dn.y < 0.0f;
    r.normal = normalize(n);
    r.id = filterGuideStoredId(g);
    return r;
}
uint filterGuideId(uint objectId) { return objectId & 0xFFFFu; }

// The a-trous passes' guide of a pool texel, packed once per frame (docs/caustics.md "Cost"): x the
// linear depth (32-bit float bits), y the normal as octahedral 2 x unorm16 (below 1e-4 rad), z the
// object id, w the depth slope (2 x half). Unpacked by atrous_thread.h (atrousGuide).
uint4 filterPackAtrousGuide(float depth, float3 n, uint id, float2 gradZ) {
    float2 e = dot(abs(n), float3(1.0f, 1.0f, 1.0f)) > 0.0f ? octEncode(n) : float2(0.0f, 0.0f);
    uint2 q = uint2(round(clamp(e * 0.5f + 0.5f, 0.0f, 1.0f) * 65535.0f));
    return uint4(filterFloatToBits(depth), q.x | (q.y << 16), id, filterPackHalf2(gradZ));
}

// This frame's object id, pre-exposed luminance and linear depth over the group's region (filter_common.h),
// loaded once per group: the rejection test's 3x3 and the depth slopes read them there instead of
// fetching each texel up to nine times per group (docs/caustics.md "Cost").
CAUSTICS_GROUPSHARED uint sTemporalId[kFilterRegion * kFilterRegion];
CAUSTICS_GROUPSHARED float sTemporalLuminance[kFilterRegion * kFilterRegion];
CAUSTICS_GROUPSHARED float sTemporalDepth[kFilterRegion * kFilterRegion];

// Fills the region (id 0 outside the view); every thread of the group calls it (a barrier).
void temporalLoadRegion(int2 origin, uint local, int2 size) {
    for (uint i = local; i < uint(kFilterRegion * kFilterRegion); i += kFilterGroupThreads) {
        int2 q = filterRegionPixel(i, origin);
        int2 t = filterInside(q, size.x, size.y) ? SPECULAR_INPUT_TEXEL(q, FILTER_LIST_ORDER_ON) : int2(-1, -1);
        sTemporalId[i] = FILTER_INPUT_UINT(gObjectId, t);
        sTemporalLuminance[i] = filterLuminance(FILTER_INPUT(current, t).rgb * params.preExposure);
        sTemporalDepth[i] = FILTER_INPUT(gLinearDepth, t).r;
    }
    CAUSTICS_GROUP_BARRIER();
}

// Last frame's pool texel of screen texel q, or (-1, -1) where its tile kept no history.
int2 temporalHistoryTexel(int2 q) {
    uint slot = CAUSTICS_TEXEL_UINT(previousSlots, filterTileOfPixel(q));
    return slot == kFilterNoSlot ? int2(-1, -1) : filterPoolTexel(slot, q);
}

// True when this frame's caustic around p is inconsistent with the history (the caustic moved: a light or
// an object moved, which the camera reprojection cannot follow): over the 3x3 taps of this object (history
// texels nearest to the reprojected point, offset alike) the sums of this frame's luminance C and of the
// history's mean H differ by more than 3 deviations of one frame's 3x3 sum (the taps' per-frame
// variances, temporal moments) plus 2 photons (q, the smallest non-zero luminance of this frame in the
// 3x3): a caustic of ~1 photon per pixel per frame that leaves is caught in one frame, 3 photons where the
// history was dark start a new one; stray photons do not; nor does one firefly (temporalTapsContradict);
// with confirmRises a rise only when the history rose too (risePending, temporalVerdict).
uint temporalHistoryVerdict(int2 p, int2 origin, int2 nearest, int2 size, uint id, bool confirmRises, bool risePending) {
    TemporalTaps taps = temporalTapsNone();
    TEMPORAL_UNROLL for (int dy = -1; dy <= 1; ++dy) {
        TEMPORAL_UNROLL for (int dx = -1; dx <= 1; ++dx) {
            int2 q = p + int2(dx, dy), hq = nearest + int2(dx, dy);
            if (!filterInside(q, size.x, size.y) || !filterInside(hq, size.x, size.y)) continue;
            int2 ht = temporalHistoryTexel(hq);
            if (ht.x < 0) continue;
            // Both history texels are fetched before any test on them: the nine taps' fetches overlap
            // instead of waiting on each other (docs/caustics.md "Cost").
            uint2 guide = CAUSTICS_TEXEL(historyGuides, ht).xy;
            float4 history = CAUSTICS_TEXEL(historyColor, ht) * params.historyScale;
            int r = filterRegionIndex(q, origin);
            if (sTemporalId[r] != id || filterGuideStoredId(guide) != filterGuideId(id)) continue;
            taps = temporalTapAdd(taps, sTemporalLuminance[r], filterLuminance(history.rgb), history.a * history.a);
        }
    }
    return temporalVerdict(taps, confirmRises, risePending);
}

// The disocclusion test of a history texel's guide: the same object, depth within tolerance, normals
// within ~25 degrees.
bool temporalGuidesAgree(FilterGuide hg, uint id, float depth, float tolerance, float3 n) {
    return hg.id == filterGuideId(id) && abs(hg.depth - depth) <= tolerance && dot(hg.normal, n) >= 0.9f;
}

// Screen-space derivative of linear depth along `axis`: the smaller one-sided difference on the same
// object, so a neighbour across a depth edge does not make the a-trous plane test lenient.
float temporalDepthSlope(int2 p, int2 origin, int2 axis, int2 size, float z, uint id) {
    float slope = 3.0e38f;
    int2 ahead = p + axis, behind = p - axis;
    int a = filterRegionIndex(ahead, origin), b = filterRegionIndex(behind, origin);
    if (filterInside(ahead, size.x, size.y) && sTemporalId[a] == id) slope = sTemporalDepth[a] - z;
    if (filterInside(behind, size.x, size.y) && sTemporalId[b] == id) {
        float back = z - sTemporalDepth[b];
        if (abs(back) < abs(slope)) slope = back;
    }
    return slope < 3.0e38f ? slope : 0.0f;
}

// Where the caustic at p was last frame, minus where it is (common/caster_motion.h): the mean receiver
// shift of the photons that reached p's 3x3 this frame (the 3x3 fills the pixels no photon reached
// inside a moving caustic); zero where none did.
float4 temporalCasterShift(int2 p, int2 size) {
    int3 sum = int3(0, 0, 0);
    uint photons = 0u;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            int2 q = p + int2(dx, dy);
            if (!filterInside(q, size.x, size.y)) continue;
            uint i = kCasterMotionWords * uint(q.y * size.x + q.x);
            sum += int3(int(casterMotionLoad(i)), int(casterMotionLoad(i + 1u)), int(casterMotionLoad(i + 2u)));
            photons += casterMotionLoad(i + 3u);
        }
    }
    // w: 1 where a photon reached the 3x3.
    return photons > 0u ? float4(float3(sum) / (kCasterMotionScale * float(photons)), 1.0f) : float4(0.0f, 0.0f, 0.0f, 0.0f);
}

// Where world point x on instance i was last frame (its rows of prev x inverse(current)).
float3 temporalInstancePrevious(uint instance, float3 x) {
    uint r = kCasterMotionRowsPerInstance * instance;
    return instanceRowsApply(instanceMotionLoad(r), instanceMotionLoad(r + 1u), instanceMotionLoad(r + 2u), x);
}

// The history colour at texel-centre position base + f by Catmull-Rom (4x4 texels) instead of
// bilinear: a caustic carried by a moving caster is resampled between texels every frame, and bilinear
// resampling blurred a one-pixel focal line over three pixels in 16 frames (docs/caustics.md "Moving
// casters"). Kept within the 2x2 texels' range (no ringing, no negative radiance); `bilinear` where a
// tap lies outside the view, has no history or another object.
float3 temporalCatmullRom(int2 base, float2 f, uint id, float3 bilinear) {
    float2 f2 = f * f, f3 = f2 * f;
    float2 w[4];
    w[0] = -0.5f * f3 + f2 - 0.5f * f;
    w[1] = 1.5f * f3 - 2.5f * f2 + 1.0f;
    w[2] = -1.5f * f3 + 2.0f * f2 + 0.5f * f;
    w[3] = 0.5f * f3 - 0.5f * f2;
    int2 size = int2(camera.frame.xy);
    float3 sum = float3(0.0f, 0.0f, 0.0f);
    float3 lo = float3(3.0e38f, 3.0e38f, 3.0e38f), hi = float3(0.0f, 0.0f, 0.0f);
    for (int j = 0; j < 4; ++j) {
        for (int i = 0; i < 4; ++i) {
            int2 q = base + int2(i - 1, j - 1);
            if (!filterInside(q, size.x, size.y)) return bilinear;
            int2 ht = temporalHistoryTexel(q);
            if (ht.x < 0) return bilinear;
            if (filterUnpackGuide(CAUSTICS_TEXEL(historyGuides, ht).xy).id != filterGuideId(id)) return bilinear;
            float3 c = CAUSTICS_TEXEL(historyColor, ht).rgb * params.historyScale;
            sum += (w[i].x * w[j].y) * c;
            if (i >= 1 && i <= 2 && j >= 1 && j <= 2) {
                lo = min(lo, c);
                hi = max(hi, c);
            }
        }
    }
    return clamp(sum, lo, hi);
}

// Whether a rise at p waits for the next frame (TemporalParams::confirmRises): every pixel of the second
// type's run; merged, the specular pixels (the glass, where the second type lies; common/specular_list.h).
bool temporalConfirmsRises(int2 p, uint id) {
    if (params.confirmRises == kTemporalConfirmEvery) return true;
    return params.confirmRises == kTemporalConfirmSpecular && gbufferTexelIsSpecular(id, CAUSTICS_TEXEL(gOptics, p));
}

void temporalThread(uint group, uint2 local) {
    int2 origin = filterTileOf(tilesLoad(group)) * kFilterTileSize;
    int2 p = origin + int2(local);
    int2 size = int2(camera.frame.xy);
    temporalLoadRegion(origin, local.y * uint(kFilterTileSize) + local.x, size);
    if (!filterInside(p, size.x, size.y)) return;
    int2 pool = filterPoolTexel(group, p);
    int2 inputTexel = SPECULAR_INPUT_TEXEL(p, FILTER_LIST_ORDER_ON);
    float3 cur = FILTER_INPUT(current, inputTexel).rgb * params.preExposure;
    float l = filterLuminance(cur);
    float4 depthGuide = FILTER_INPUT(gLinearDepth, inputTexel);   // .yzw: the second type's motion (motionGuides)
    float depth = depthGuide.r;
    float3 n = FILTER_INPUT(gNormal, inputTexel).xyz;
    uint id = FILTER_INPUT_UINT(gObjectId, inputTexel);
    float3 color = cur;
    float moment2 = l * l;
    float historyLength = 1.0f;
    bool risePending = false;   // this frame's: a rise kept for the next frame to confirm
    if (params.historyValid != 0u && id != 0u && depth > 0.0f) {
        float3 world = cameraWorldPosition(camera, float2(p) + 0.5f, depth);
        // The history of a caustic whose caster moved lies where the caustic was (its receiver stays).
        float3 source = world;
        bool carried = false;   // the history moves with a caster (temporalCatmullRom)
        if (params.casterMotion != 0u && params.motionGuides == 0u) {
            float4 shift = temporalCasterShift(p, size);
            source += shift.xyz;
            carried = shift.w > 0.0f;
        }
        // A pixel that shows a moved instance (a glass ball and what is seen through it, a moving
        // receiver) takes its history from where that point of the instance was, unless photons carried
        // the caustic there from their caster (above). Still instances' rows are the identity.
        if (!carried && params.objectMotion != 0u && params.motionGuides == 0u && id - 1u < params.instanceCount) {
            source = temporalInstancePrevious(id - 1u, world);
            float3 moved = source - world;
            carried = dot(moved, moved) > 1e-10f;   // over 10 um: not rounding
        }
        float4 clip = mul(camera.prevViewProj, float4(source, 1.0f));
        if (params.motionGuides != 0u) clip.w = depthGuide.w;
        if (clip.w > 0.0f) {
            // Texel-centre coordinates.
            float2 prev = params.motionGuides != 0u ? float2(p) + float2(depthGuide.y, depthGuide.z)
                                                    : (clip.xy / clip.w * 0.5f + 0.5f) * float2(size) - 0.5f;
            int2 base = int2(floor(prev));
            float2 f = prev - float2(base);
            float tolerance = clip.w * temporalRelativeDepthTolerance(camera.forward.w, float(size.y), n,
                                                                      normalize(camera.eye.xyz - world));
            // The second type seen through a still view (its guide's motion under kTemporalStillView
            // pixels: the camera and the glass did not move): the pixel's history is the mean of its
            // jittered camera paths, whichever receiver each reached (a glass's rim, a curved mirror),
            // so the receiver's guides are not tested (docs/caustics.md "Second-type guides").
            bool stillView = params.motionGuides != 0u && dot(depthGuide.yz, depthGuide.yz) < kTemporalStillView * kTemporalStillView;
            float3 hColor = float3(0.0f, 0.0f, 0.0f), hMoments = float3(0.0f, 0.0f, 0.0f);
            float wSum = 0.0f;
            bool historyRose = false;   // a blended texel's rise is pending
            TEMPORAL_UNROLL for (int i = 0; i < 4; ++i) {
                int2 o = int2(i & 1, i >> 1);
                int2 q = base + o;
                if (!filterInside(q, size.x, size.y)) continue;
                int2 ht = temporalHistoryTexel(q);
                if (ht.x < 0) continue;
                // The colour with the guide, before the tests on the guide (as in temporalHistoryVerdict).
                FilterGuide hg = filterUnpackGuide(CAUSTICS_TEXEL(historyGuides, ht).xy);
                float4 history = CAUSTICS_TEXEL(historyColor, ht) * params.historyScale;
                if (!stillView && !temporalGuidesAgree(hg, id, clip.w, tolerance, n)) continue;
                float w = (o.x == 1 ? f.x : 1.0f - f.x) * (o.y == 1 ? f.y : 1.0f - f.y);
                hColor += w * history.rgb;
                // Per-tap variance, not the moments: mixing the moments of neighbouring texels would add
                // their signal difference (a focal spot's edge) to the variance.
                hMoments += w * float3(filterLuminance(history.rgb), history.a * history.a, hg.historyLength);
                wSum += w;
                historyRose = historyRose || (w > 0.0f && hg.risePending);
            }
            // The test needs variances from the moments: histories shorter than kTemporalTrustedHistory
            // frames are short already (their lag is at most that long).
            uint verdict = wSum > 0.01f && hMoments.z / wSum >= kTemporalTrustedHistory
                               ? temporalHistoryVerdict(p, origin, int2(floor(prev + 0.5f)), size, id,
                                                        temporalConfirmsRises(p, id), historyRose)
                               : kTemporalKeep;
            if (wSum > 0.01f && verdict != kTemporalDrop) {
                risePending = verdict == kTemporalKeepRisePending;
                hColor /= wSum;
                if (carried && wSum > 0.999f) hColor = temporalCatmullRom(base, f, id, hColor);
                hMoments /= wSum;
                hMoments.y += hMoments.x * hMoments.x;   // back to E[l^2] of the blended history
                historyLength = min(hMoments.z + 1.0f, params.maxHistory);
                float alpha = 1.0f / historyLength;
                color = lerp(hColor, cur, alpha);
                moment2 = lerp(hMoments.y, moment2, alpha);
            }
        }
    }
    // The variance leaves as a standard deviation: E[l^2] - E[l]^2 cancels in 32 bits, and the deviation
    // has the range of the radiance, which half precision holds (docs/caustics.md "Memory").
    float lm = filterLuminance(color);
    float deviation = sqrt(max(0.0f, moment2 - lm * lm));
    float2 gradZ = float2(temporalDepthSlope(p, origin, int2(1, 0), size, depth, id), temporalDepthSlope(p, origin, int2(0, 1), size, depth, id));
    CAUSTICS_IMAGE_STORE(outColor, pool, filterNearestHalf4(float4(color, deviation)));
    uint2 guide = filterPackGuide(depth, historyLength, risePending, n, id);
#if defined(CAUSTICS_LANG_HLSL)
    outGuides[pool] = guide;
#else
    imageStore(outGuides, pool, uvec4(guide, 0u, 0u));
#endif
    CAUSTICS_IMAGE_STORE(outFilterGuide, pool, filterPackAtrousGuide(depth, n, id, gradZ));
}

#endif  // CAUSTICS_PASS_CAUSTIC_TEMPORAL_THREAD_H
