#ifndef CAUSTICS_PASS_CAUSTIC_ATROUS_H
#define CAUSTICS_PASS_CAUSTIC_ATROUS_H
// caustics.atrous.N in the shared dialect (docs/shaders.md): one edge-aware a-trous iteration of step
// 2^N (Dammertz et al. 2010 with SVGF's edge-stopping weights, Schied et al. 2017), energy-preserving:
// every source q hands each receiver p of its 5x5 holed neighbourhood the share w(q -> p) / W_q of its
// radiance, W_q = sum_p w(q -> p), so a source's shares add up to 1 (docs/caustics.md "Filter",
// "Spatial"). Two passes per iteration over the tile list (docs/caustics.md "Cost"):
//   caustics.atrous.N.weights   W_q of every pixel of the tile (atrous_weights.comp / .hlsl)
//   caustics.atrous.N           the shares (atrous.comp / .hlsl into the pool; atrous_last.comp / .hlsl,
//                               kAtrousLast, into caustics.radiance in radiance units)
// Each tap is fetched (docs/caustics.md "Cost" has what a shared-memory region measured).
#include "filter_common.h"

CAUSTICS_SHARED_BEGIN
// Push constants (atrous_bindings.h), 24 bytes.
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
};

// B3-spline a-trous kernel taps for |offset| / step = 0, 1, 2 (1/16 (1 4 6 4 1)).
CAUSTICS_FN float atrousKernelTap(int k) { return k == 0 ? 0.375f : (k == 1 ? 0.25f : 0.0625f); }

// Weight with which source pixel q spreads its radiance to pixel p = q + offset (SVGF's edge-stopping
// functions, Schied et al. 2017, eq. 3-5, with a Gaussian luminance term):
//   w_z = exp(-|z_p - z_q - grad z_q . offset| / (|grad z_q . offset| + (0.002 + 0.02 j) z_q step + j |grad z_q|_1))
//         (a plane passes; j = depthJitter, AtrousParams)
//   w_n = max(0, n_q . n_p)^128
//   w_l = exp(-d^2 / 2),  d = |l_p - l_q| / (sigma_l sqrt(Var_q + Var_p))
// times the B3 kernel; the caller checks the object id. The luminance term uses the variance of the
// difference, so it is symmetric in p and q: no net flow between two pixels whose difference is noise.
// Gaussian, not SVGF's exp(-d): one deviation keeps 0.61 of the weight, three keep 0.011, so a fold line
// or a cusp stops the spreading (docs/caustics.md "Spatial"). Two reciprocals and one exponential per
// weight (d^2 without its square root, w_n by squarings, w_z w_l in one exponential): the a-trous passes
// evaluate it 50 times per pixel and iteration, and the GPU's special-function units are its bound.
// `tap` is the offset in steps (-2..2 per axis): p = q + stepWidth tap.
CAUSTICS_FN float atrousSpreadWeight(int2 tap, int stepWidth, float zq, float zp, float2 gradZq, float3 nq, float3 np,
                                     float lq, float lp, float varianceQ, float varianceP, float sigmaLuminance,
                                     float depthJitter) {
    int2 k = abs(tap);
    float planar = dot(gradZq, float2(tap * stepWidth));
    float tolerance = abs(planar) + (0.002f + 0.02f * depthJitter) * zq * float(stepWidth) +
                      depthJitter * (abs(gradZq.x) + abs(gradZq.y));
    float depthTerm = abs(zp - zq - planar) / tolerance;
    float difference = lp - lq;
    // max(): two pixels of no variance and equal luminance keep the weight (0 / tiny), unequal ones lose it.
    float d2 = difference * difference / max(sigmaLuminance * sigmaLuminance * (varianceQ + varianceP), 1e-30f);
    float c = max(0.0f, dot(nq, np));
    c *= c;   // ^2
    c *= c;   // ^4
    c *= c;   // ^8
    c *= c;   // ^16
    c *= c;   // ^32
    c *= c;   // ^64
    c *= c;   // ^128
    return atrousKernelTap(k.x) * atrousKernelTap(k.y) * c * exp(-depthTerm - 0.5f * d2);
}
CAUSTICS_SHARED_END

#if !defined(CAUSTICS_LANG_CPP)
#include "atrous_thread.h"
#endif

#endif  // CAUSTICS_PASS_CAUSTIC_ATROUS_H
