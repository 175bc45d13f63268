#ifndef CAUSTICS_PASS_CAUSTIC_ATROUS_H
#define CAUSTICS_PASS_CAUSTIC_ATROUS_H
// caustics.atrous.N in the shared dialect (docs/shaders.md): one edge-aware a-trous iteration of step
// 2^N (Dammertz et al. 2010 with SVGF's edge-stopping weights, Schied et al. 2017), energy-preserving:
// every source q hands each receiver p of its 5x5 holed neighbourhood the share w(q -> p) / W_q of its
// radiance, W_q = sum_p w(q -> p), so a source's shares add up to 1 (docs/caustics.md "Filter",
// "Spatial"). One pass per iteration (docs/caustics.md "Cost"): a group loads a lattice of 16 x 16
// pool texels (8 x 8 receivers and a 4-point apron) into shared memory, computes W_q of its 12 x 12
// sources there, then spreads. A step-s iteration only mixes pixels congruent modulo s, so a group
// works on one such lattice (pixels origin + s (i, j)), never on a contiguous tile at a large step:
// the apron stays 4 points at every step. Entries: atrous.comp / atrous.hlsl (into the pool) and
// atrous_last.comp / atrous_last.hlsl (kAtrousLast: into caustics.radiance, in radiance units).
#include "filter_common.h"

CAUSTICS_SHARED_BEGIN
// Push constants (atrous_bindings.h), 20 bytes.
struct AtrousParams {
    int stepWidth;
    int width;
    int height;
    float sigmaLuminance;
    float invPreExposure;   // the last iteration: pool units (pre-exposed) -> radiance
};

CAUSTICS_CONST int kAtrousApron = 4;           // receivers' sources (2) and the sources' receivers (2)
CAUSTICS_CONST int kAtrousRegion = 16;         // lattice points per side in shared memory: 8 + 2 x 4
CAUSTICS_CONST int kAtrousSources = 12;        // sources per side: 8 + 2 x 2

// B3-spline a-trous kernel taps for |offset| / step = 0, 1, 2 (1/16 (1 4 6 4 1)).
CAUSTICS_FN float atrousKernelTap(int k) { return k == 0 ? 0.375f : (k == 1 ? 0.25f : 0.0625f); }

// Weight with which source pixel q spreads its radiance to pixel p = q + offset (SVGF's edge-stopping
// functions, Schied et al. 2017, eq. 3-5, with a Gaussian luminance term):
//   w_z = exp(-|z_p - z_q - grad z_q . offset| / (|grad z_q . offset| + 0.002 z_q step))   (a plane passes)
//   w_n = max(0, n_q . n_p)^128
//   w_l = exp(-d^2 / 2),  d = |l_p - l_q| / (sigma_l sqrt(Var_q + Var_p))
// times the B3 kernel; the caller checks the object id. The luminance term uses the variance of the
// difference, so it is symmetric in p and q: no net flow between two pixels whose difference is noise.
// Gaussian, not SVGF's exp(-d): one deviation keeps 0.61 of the weight, three keep 0.011, so a fold line
// or a cusp stops the spreading (docs/caustics.md "Spatial").
CAUSTICS_FN float atrousSpreadWeight(int2 offset, int stepWidth, float zq, float zp, float2 gradZq, float3 nq, float3 np,
                                     float lq, float lp, float varianceQ, float varianceP, float sigmaLuminance) {
    int2 k = abs(offset) / stepWidth;
    float planar = dot(gradZq, float2(offset));
    float depthTerm = abs(zp - zq - planar) / (abs(planar) + 0.002f * zq * float(stepWidth));
    float d = abs(lp - lq) / (sigmaLuminance * sqrt(varianceQ + varianceP) + 1e-20f);
    float c = max(0.0f, dot(nq, np));
    c *= c;   // ^2
    c *= c;   // ^4
    c *= c;   // ^8
    c *= c;   // ^16
    c *= c;   // ^32
    c *= c;   // ^64
    c *= c;   // ^128: seven squarings, not pow (a log and an exp per weight)
    // w_z w_l in one exponential.
    return atrousKernelTap(k.x) * atrousKernelTap(k.y) * c * exp(-depthTerm - 0.5f * d * d);
}

// The lattices of a step-s iteration: the screen's tiles form blocks of s x s tiles (8s x 8s pixels);
// block b holds s^2 lattices, lattice c (0 <= c < s per axis) being the pixels 8 s b + c + s (i, j),
// 0 <= i, j < 8. Each lattice has one designated tile, b s + c, whose group runs it when listed; the
// lattices whose designated tile is not listed are run by the block's first listed tile (row-major),
// so every pixel of a listed tile is filtered exactly once (atrousThread; AtrousBody.* in
// pass_body_tests).
CAUSTICS_FN int2 atrousBlock(int2 tile, int stepWidth) { return tile / stepWidth; }
CAUSTICS_FN int2 atrousOwnLattice(int2 tile, int stepWidth) { return tile - atrousBlock(tile, stepWidth) * stepWidth; }
CAUSTICS_FN int2 atrousLatticeOrigin(int2 block, int2 lattice, int stepWidth) {
    return block * (kFilterTileSize * stepWidth) + lattice;
}
CAUSTICS_FN int2 atrousLatticePixel(int2 origin, int2 point, int stepWidth) { return origin + point * stepWidth; }
CAUSTICS_SHARED_END

#if !defined(CAUSTICS_LANG_CPP)
#include "atrous_thread.h"
#endif

#endif  // CAUSTICS_PASS_CAUSTIC_ATROUS_H
