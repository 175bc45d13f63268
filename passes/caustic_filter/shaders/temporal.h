#ifndef CAUSTICS_PASS_CAUSTIC_TEMPORAL_H
#define CAUSTICS_PASS_CAUSTIC_TEMPORAL_H
// caustics.temporal in the shared dialect (docs/shaders.md): temporal accumulation (SVGF, Schied et al.
// 2017, section 4.1; docs/caustics.md "Temporal", "Moving caustics"). The pixel's world position goes
// through last frame's viewProj; of the 2x2 history texels around that point, those of the same object
// with a linear depth (clip w) and normal that agree are blended bilinearly (disocclusion test). The
// history length n (a sample count, capped at maxHistory) makes the blend 1/n: until the cap the result
// is the plain mean of every frame that saw the surface point, then an exponential average with weight
// 1/maxHistory. The luminance moments accumulate the same way for the variance estimate. A history that
// this frame's photons contradict (temporalHistoryVerdict: the caustic moved) is dropped. Dispatched
// over the tile list; a history texel exists only where last frame's slot map gave its tile a pool
// tile. The history is ping-ponged (docs/caustics.md "History and guides"): this pass reads last frame's
// pool and writes this frame's (the result before any spatial pass, and its guides), and, once per
// frame, the a-trous passes' packed guide. Everything in the pool is pre-exposed half precision.
// Entries: temporal.comp, temporal.hlsl; the thread function is temporal_thread.h.
#include "filter_common.h"

CAUSTICS_SHARED_BEGIN
// Push constants (temporal_bindings.h), 36 bytes.
struct TemporalParams {
    uint historyValid;
    float maxHistory;     // CausticsSettings::filterMaxHistory
    float preExposure;    // this frame's (docs/caustics.md "Memory")
    float historyScale;   // this frame's pre-exposure over the one the history was stored with
    // 1: gLinearDepth is the second type's guide (depth, motion x, motion y, last frame's depth;
    // docs/caustics.md "Second-type guides"): reproject with the receiver's own motion, not the camera ray's.
    uint motionGuides;
    // 1: casterMotion holds this frame's caster motion sums (docs/caustics.md "Moving casters").
    uint casterMotion;
    // 1: instanceMotion holds the rows of every instance (common/caster_motion.h): a pixel showing a moved
    // instance takes its history from where that point was (docs/caustics.md "Moving objects").
    uint objectMotion;
    uint instanceCount;   // instances the rows cover
    // kTemporalConfirm*: where a rise drops the history only when the frame before rose too
    // (temporalVerdict): the pixels that hold the second type (docs/caustics.md "Moving caustics").
    uint confirmRises;
};
CAUSTICS_CONST uint kTemporalConfirmNone = 0u;       // the first type alone
CAUSTICS_CONST uint kTemporalConfirmEvery = 1u;      // the second type's own run
CAUSTICS_CONST uint kTemporalConfirmSpecular = 2u;   // both types merged: the specular pixels (gOptics)
CAUSTICS_CONST float kTemporalRejectDeviations = 3.0f;
CAUSTICS_CONST float kTemporalTrustedHistory = 4.0f;
// A second-type guide whose motion is under this (pixels) shows a still view (temporal_thread.h).
CAUSTICS_CONST float kTemporalStillView = 0.125f;

// Relative linear-depth tolerance for a reprojected history tap up to one pixel away: 1 % plus the
// depth change across two pixel footprints on a surface seen at the given angle (the same footprint
// argument as the first-type splat's depth test, docs/caustics.md "Forward trace").
CAUSTICS_FN float temporalRelativeDepthTolerance(float tanHalfFovY, float imageHeight, float3 normal, float3 toEye) {
    float cosView = max(abs(dot(normal, toEye)), 0.05f);
    float tanView = sqrt(max(0.0f, 1.0f - cosView * cosView)) / cosView;
    return 0.01f + 2.0f * (2.0f * tanHalfFovY / imageHeight) * tanView;
}

// The history test (docs/caustics.md "Moving caustics"): C and H the 3x3 sums of this frame's luminance
// and of the history's mean, v the sum of the taps' per-frame variances, quantum one photon's luminance.
CAUSTICS_FN bool temporalContradicts(float c, float h, float v, float quantum) {
    return abs(c - h) > kTemporalRejectDeviations * sqrt(v) + 2.0f * quantum;
}

// The test's taps, added one by one (temporalTapAdd): the sums and, apart, the brightest tap, which
// temporalTapsContradict leaves out of both sums when it is a firefly: above its history and at least
// kTemporalFireflyRatio times as bright as every other tap this frame. One such sample in nine is a rare
// path, which the 1/n average takes at its weight, not a caustic that moved into the 3x3 (that brightens
// its neighbours too; a fall is never left out). docs/caustics.md "Moving caustics".
CAUSTICS_CONST float kTemporalFireflyRatio = 4.0f;
struct TemporalTaps {
    float c, h, v, quantum;   // as temporalContradicts; quantum 0 until a lit tap
    float top, topH;          // the brightest tap's l and its history
    float second;             // the second largest l
};
CAUSTICS_FN TemporalTaps temporalTapsNone() {
    TemporalTaps t;
    t.c = 0.0f;
    t.h = 0.0f;
    t.v = 0.0f;
    t.quantum = 0.0f;
    t.top = 0.0f;
    t.topH = 0.0f;
    t.second = 0.0f;
    return t;
}
// One tap: this frame's luminance l, the history's mean hl and per-frame variance.
CAUSTICS_FN TemporalTaps temporalTapAdd(TemporalTaps t, float l, float hl, float variance) {
    t.c += l;
    t.h += hl;
    t.v += variance;
    if (l > 0.0f) t.quantum = t.quantum > 0.0f ? min(t.quantum, l) : l;
    if (l > t.top) {
        t.second = t.top;
        t.top = l;
        t.topH = hl;
    } else {
        t.second = max(t.second, l);
    }
    return t;
}
CAUSTICS_FN bool temporalTapsFirefly(TemporalTaps t) { return t.top > t.topH && t.top >= kTemporalFireflyRatio * t.second; }
CAUSTICS_FN bool temporalTapsContradict(TemporalTaps t) {
    return temporalTapsFirefly(t) ? temporalContradicts(t.c - t.top, t.h - t.topH, t.v, t.quantum)
                                  : temporalContradicts(t.c, t.h, t.v, t.quantum);
}
// Whether the tested sums rose above the history (the firefly left out as temporalTapsContradict does).
CAUSTICS_FN bool temporalTapsRose(TemporalTaps t) {
    return temporalTapsFirefly(t) ? t.c - t.top > t.h - t.topH : t.c > t.h;
}

// What the temporal pass does with a history (docs/caustics.md "Moving caustics"). With confirmRises a
// rise drops it only when the history's own frame had risen too (risePending, kept in the history
// guide): a caustic that moved in is still there a frame later, one rare sample is not. The second
// type needs it: a photon lies in the gather disks of several neighbouring pixels (more than one tap of
// the 3x3), so one photon, or one rare path's bright one, read as a caustic that moved in, restarted
// the history at full strength and biased a still view bright (2-4x through the built-in ball after 32
// frames). A fall is never a rare sample: it drops the history at once.
CAUSTICS_CONST uint kTemporalKeep = 0u;
CAUSTICS_CONST uint kTemporalDrop = 1u;
CAUSTICS_CONST uint kTemporalKeepRisePending = 2u;
CAUSTICS_FN uint temporalVerdict(TemporalTaps t, bool confirmRises, bool risePending) {
    if (!temporalTapsContradict(t)) return kTemporalKeep;
    if (!confirmRises || risePending || !temporalTapsRose(t)) return kTemporalDrop;
    return kTemporalKeepRisePending;
}
CAUSTICS_SHARED_END

#if !defined(CAUSTICS_LANG_CPP)
#include "temporal_thread.h"
#endif

#endif  // CAUSTICS_PASS_CAUSTIC_TEMPORAL_H
