#ifndef CAUSTICS_PASS_CAUSTIC_ATROUS_H
#define CAUSTICS_PASS_CAUSTIC_ATROUS_H
// caustics.atrous.N in the shared dialect (docs/shaders.md): one edge-aware a-trous iteration of step
// 2^N (Dammertz et al. 2010 with SVGF's edge-stopping weights, Schied et al. 2017), energy-preserving:
// every source q hands each receiver p of its 5x5 holed neighbourhood the share w(p, q) / W_q of its
// radiance, W_q = sum_p w(p, q), so a source's shares add up to 1 (docs/caustics.md "Filter",
// "Spatial"). The weight is symmetric, so each pair's is evaluated once per iteration, by the pixel of
// the pair that comes first in scan order. Two passes per iteration over the tile list, the first
// iteration's weight sums zeroed by caustics.variance (docs/caustics.md "Cost"):
//   caustics.atrous.N.pairs     w to the 12 later neighbours of every pixel, packed, and added to both
//                               pixels' W_q (atrous_pairs.comp / .hlsl)
//   caustics.atrous.N           the shares (atrous.comp / .hlsl into the pool; atrous_last.comp / .hlsl,
//                               kAtrousLast, into caustics.radiance in radiance units)
// Each tap's colour and guide are fetched (docs/caustics.md "Cost" has what a shared-memory region measured).
#include "filter_common.h"

CAUSTICS_SHARED_BEGIN
// Push constants (atrous_bindings.h), 32 bytes.
struct AtrousParams {
    int stepWidth;
    int width;
    int height;
    float sigmaLuminance;
    float invPreExposure;   // the last iteration: pool units (pre-exposed) -> radiance
    // 0 for the camera G-buffer (rasterised at pixel centres, planar surfaces seen directly); 1 for the
    // second type's guides: read where a backward ray jittered inside its pixel reached the receiver (off
    // by up to a pixel of depth slope), through glass that bends the receiver's depth away from a plane
    // over the larger steps (2 % of the depth per step; docs/caustics.md "Second-type guides").
    float depthJitter;
    // The weight sums W alternate between two regions of caustics.atrous.sums, a pool's texels each:
    // this iteration's first word, and the next iteration's, which this iteration's shares pass zeroes
    // (kAtrousNoNextSums after the last; caustics.variance zeroes the first iteration's region).
    uint sumsBase;
    uint nextSumsBase;
};

CAUSTICS_CONST uint kAtrousNoNextSums = 0xFFFFFFFFu;

// B3-spline a-trous kernel taps for |offset| / step = 0, 1, 2 (1/16 (1 4 6 4 1)).
CAUSTICS_FN float atrousKernelTap(int k) { return k == 0 ? 0.375f : (k == 1 ? 0.25f : 0.0625f); }

// The symmetric weight of pixels p and q = p + stepWidth tap (SVGF's edge-stopping functions, Schied et
// al. 2017, eq. 3-5, with a Gaussian luminance term), with the plane test on the pair's mean depth slope
// g = (grad z_p + grad z_q) / 2 and mean depth z = (z_p + z_q) / 2:
//   w_z = exp(-|z_q - z_p - g . offset| / (|g . offset| + (0.002 + 0.02 j) z step + j |g|_1))
//         (a plane passes; j = depthJitter, AtrousParams)
//   w_n = max(0, n_p . n_q)^128
//   w_l = exp(-d^2 / 2),  d = |l_q - l_p| / (sigma_l sqrt(Var_p + Var_q))
// times the B3 kernel; the caller checks the object id. Every term is unchanged when p and q swap (the
// offset changes sign with z_q - z_p), so w(p, q) = w(q, p): a pair is evaluated once and serves as
// p's share of q and q's of p. The luminance term uses the variance of the difference: no net flow
// between two pixels whose difference is noise. Gaussian, not SVGF's exp(-d): one deviation keeps 0.61
// of the weight, three keep 0.011, so a fold line or a cusp stops the spreading (docs/caustics.md
// "Spatial"). Two reciprocals and one exponential (d^2 without its square root, w_n by squarings,
// w_z w_l in one exponential).
CAUSTICS_FN float atrousPairWeight(int2 tap, int stepWidth, float zp, float zq, float2 gradZp, float2 gradZq, float3 np,
                                   float3 nq, float lp, float lq, float varianceP, float varianceQ, float sigmaLuminance,
                                   float depthJitter) {
    int2 k = abs(tap);
    float2 slope = 0.5f * (gradZp + gradZq);
    float planar = dot(slope, float2(tap * stepWidth));
    float tolerance = abs(planar) + (0.002f + 0.02f * depthJitter) * 0.5f * (zp + zq) * float(stepWidth) +
                      depthJitter * (abs(slope.x) + abs(slope.y));
    float depthTerm = abs(zq - zp - planar) / tolerance;
    float difference = lq - lp;
    // max(): two pixels of no variance and equal luminance keep the weight (0 / tiny), unequal ones lose it.
    float d2 = difference * difference / max(sigmaLuminance * sigmaLuminance * (varianceP + varianceQ), 1e-30f);
    float c = max(0.0f, dot(np, nq));
    c *= c;   // ^2
    c *= c;   // ^4
    c *= c;   // ^8
    c *= c;   // ^16
    c *= c;   // ^32
    c *= c;   // ^64
    c *= c;   // ^128
    return atrousKernelTap(k.x) * atrousKernelTap(k.y) * c * exp(-depthTerm - 0.5f * d2);
}

// A pixel's weight to itself: the kernel's centre tap (every term is 1 for p = q).
CAUSTICS_CONST float kAtrousSelfWeight = 0.140625f;   // 0.375^2

// The 12 neighbours a pixel evaluates, in tap units: those after it in scan order, (1, 0), (2, 0), then
// the rows dy = 1 and 2 from dx = -2 to 2. Their negatives are the 12 before it, whose pairs the earlier
// pixel holds at the same index.
CAUSTICS_CONST int kAtrousPairCount = 12;
CAUSTICS_FN int2 atrousPairTap(int k) { return k < 2 ? int2(k + 1, 0) : (k < 7 ? int2(k - 4, 1) : int2(k - 9, 2)); }

// A pair's weight in 10 bits, an unsigned float of 5 exponent and 5 mantissa bits (a relative step of
// 1/32, 1/64 after rounding to nearest; the B10G11R11 format's 10-bit channel, with its own bias): three
// to a 32-bit word, the 12 pairs in one RGBA32UI texel. Exponents below 6 are 0: weights below 2^-25
// (a 1.5e5th of the smallest kernel tap) are dropped, so every weight is a whole multiple of 2^-30 and
// W_q adds exactly in 32-bit fixed point (atrousFixedWeight). Every pass reads the weight through
// atrousUnpackWeight, so the shares of a source add up to 1 (W_q sums the same rounded weights).
CAUSTICS_FN uint atrousPackWeight(float w) {
    uint u = asuint(w) + 0x20000u;   // round the 23-bit mantissa to 5 bits (half up)
    int e = int(u >> 23) - 96;       // float bias 127 -> ours 31
    if (w <= 0.0f || e < 6) return 0u;
    return e > 31 ? 0x3FFu : (uint(e) << 5) | ((u >> 18) & 0x1Fu);
}
CAUSTICS_FN float atrousUnpackWeight(uint code) {
    return code == 0u ? 0.0f : asfloat(((code >> 5) + 96u) << 23 | (code & 0x1Fu) << 18);
}
// W_q in fixed point, 2^30 to 1: every unpacked weight (and the centre tap) is a whole number of units,
// and the 25 weights of a source add up to at most the kernel's sum, 1 = 2^30 < 2^32.
CAUSTICS_CONST float kAtrousFixedScale = 1073741824.0f;   // 2^30
CAUSTICS_FN uint atrousFixedWeight(float w) { return uint(w * kAtrousFixedScale); }
// Pair k's 10 bits in a packed texel.
CAUSTICS_FN uint atrousPairCode(uint4 pairs, int k) { return (pairs[k / 3] >> (10 * (k % 3))) & 0x3FFu; }
CAUSTICS_SHARED_END

#if !defined(CAUSTICS_LANG_CPP)
#include "atrous_thread.h"
#endif

#endif  // CAUSTICS_PASS_CAUSTIC_ATROUS_H
