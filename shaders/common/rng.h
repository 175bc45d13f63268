#ifndef CAUSTICS_COMMON_RNG_H
#define CAUSTICS_COMMON_RNG_H
// Random numbers shared by the GPU passes and the CPU reference: a stateless PCG hash for seeding and
// a 32-bit PCG stream (LCG step + RXS-M-XS output permutation; O'Neill 2014, "PCG: a family of simple
// fast space-efficient statistically good algorithms"; Jarzynski & Olano 2020, JCGT 9(3), "Hash
// functions for GPU rendering", which recommends exactly this hash for GPU seeding).
#include "common/lang.h"

CAUSTICS_SHARED_BEGIN

CAUSTICS_CONST uint kPcgMultiplier = 747796405u;
CAUSTICS_CONST uint kPcgIncrement = 2891336453u;

CAUSTICS_FN uint pcgPermute(uint state) {
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

CAUSTICS_FN uint pcgHash(uint v) { return pcgPermute(v * kPcgMultiplier + kPcgIncrement); }

struct Rng {
    uint state;
};

// One independent stream per (pixel or texel, light, sample, frame): each key goes through the hash
// before the next is added, so streams of neighbouring keys are decorrelated.
CAUSTICS_FN Rng rngCreate(uint pixel, uint light, uint sampleIndex, uint frame) {
    Rng rng;
    rng.state = pcgHash(pixel + pcgHash(light + pcgHash(sampleIndex + pcgHash(frame))));
    return rng;
}

CAUSTICS_FN uint rngNextUint(CAUSTICS_INOUT(Rng) rng) {
    uint old = rng.state;
    rng.state = old * kPcgMultiplier + kPcgIncrement;
    return pcgPermute(old);
}

// Uniform in [0, 1): the top 24 bits, so every value is exactly representable and 1.0 never occurs.
CAUSTICS_FN float rngNextFloat(CAUSTICS_INOUT(Rng) rng) {
    return float(rngNextUint(rng) >> 8u) * (1.0f / 16777216.0f);
}

CAUSTICS_FN float2 rngNextFloat2(CAUSTICS_INOUT(Rng) rng) {
    float a = rngNextFloat(rng);
    float b = rngNextFloat(rng);
    return float2(a, b);
}

CAUSTICS_FN float3 rngNextFloat3(CAUSTICS_INOUT(Rng) rng) {
    float a = rngNextFloat(rng);
    float b = rngNextFloat(rng);
    float c = rngNextFloat(rng);
    return float3(a, b, c);
}

CAUSTICS_SHARED_END

#endif  // CAUSTICS_COMMON_RNG_H
