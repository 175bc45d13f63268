#ifndef CAUSTICS_COMMON_RADIANCE_ATOMICS_H
#define CAUSTICS_COMMON_RADIANCE_ATOMICS_H
// Atomic accumulation of RGB radiance per pixel (3 words per pixel), for the ray-tracing stages of the
// forward splat and the gather's any-hit; GLSL and HLSL only. The authors' code adds with a non-atomic
// += (a data race); here every add is atomic:
//  - float words where the device has float atomics (GLSL GL_EXT_shader_atomic_float). HLSL has no float
//    atomic add (SM 6.6 adds only 64-bit integer atomics and bitwise float compare-exchange), so there a
//    bounded compare-exchange loop on the float's bits writes the same float bits; a contribution it
//    could not store is counted (kStatAccumulationGiveUps, causticStatsWarnings), never dropped silently;
//  - else fixed point (docs/caustics.md, "Fixed point"): value x scale, the scale 2^16 (CAUSTICS_FIXED_POINT,
//    one uint per channel) or 2^32 (CAUSTICS_FIXED_POINT_64, one uint64 per channel, where the device has
//    shaderBufferInt64Atomics) times the frame's pre-exposure, written by the host into
//    stats[kStatFixedPointScale]. Sub-LSB parts round stochastically (up with probability equal to the
//    fraction), so faint light adds up unbiased instead of vanishing; a sum that would pass the word's
//    maximum pins there and is counted (kStatSaturatedAdds, causticStatsWarnings).
// Include after the pass's generated bindings, which declare radianceWords (float, uint or uint64_t
// words) and the uint stats buffer.
#include "common/caustic_stats.h"
#include "common/lang.h"

// What differs per API: the launch index, the word type's spellings and the word atomics.
#if defined(CAUSTICS_LANG_GLSL)
#define RADIANCE_LAUNCH_ID gl_LaunchIDEXT
#if defined(CAUSTICS_FIXED_POINT_64)
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#define RadianceWord uint64_t
#define RADIANCE_WORD_MAX 0xFFFFFFFFFFFFFFFFul
#elif defined(CAUSTICS_FIXED_POINT)
#define RadianceWord uint
#define RADIANCE_WORD_MAX 0xFFFFFFFFu
#else
#extension GL_EXT_shader_atomic_float : require
#endif
#if defined(CAUSTICS_FIXED_POINT) || defined(CAUSTICS_FIXED_POINT_64)
RadianceWord radianceWordAdd(uint word, RadianceWord add) { return atomicAdd(radianceWords[word], add); }
void radianceWordPin(uint word) { atomicMax(radianceWords[word], RADIANCE_WORD_MAX); }
#else
bool radianceFloatAdd(uint word, float value) {
    atomicAdd(radianceWords[word], value);
    return true;
}
#endif
#else   // HLSL: raw buffers, byte addresses
#define RADIANCE_LAUNCH_ID DispatchRaysIndex()
#if defined(CAUSTICS_FIXED_POINT_64)
#define RadianceWord uint64_t
#define RADIANCE_WORD_MAX 0xFFFFFFFFFFFFFFFFull
#define RADIANCE_WORD_BYTES 8u
#define RADIANCE_INTERLOCKED_ADD InterlockedAdd64   // SM 6.6
#define RADIANCE_INTERLOCKED_MAX InterlockedMax64
#elif defined(CAUSTICS_FIXED_POINT)
#define RadianceWord uint
#define RADIANCE_WORD_MAX 0xFFFFFFFFu
#define RADIANCE_WORD_BYTES 4u
#define RADIANCE_INTERLOCKED_ADD InterlockedAdd
#define RADIANCE_INTERLOCKED_MAX InterlockedMax
#endif
#if defined(CAUSTICS_FIXED_POINT) || defined(CAUSTICS_FIXED_POINT_64)
RadianceWord radianceWordAdd(uint word, RadianceWord add) {
    RadianceWord old;
    radianceWords.RADIANCE_INTERLOCKED_ADD(RADIANCE_WORD_BYTES * word, add, old);
    return old;
}
void radianceWordPin(uint word) { radianceWords.RADIANCE_INTERLOCKED_MAX(RADIANCE_WORD_BYTES * word, RADIANCE_WORD_MAX); }
#else
bool radianceFloatAdd(uint word, float value) {
    uint address = 4u * word;
    uint expected = radianceWords.Load(address);
    bool stored = false;
    for (uint attempt = 0u; attempt < 1024u && !stored; ++attempt) {   // bounded: no infinite loop under contention
        uint original;
        radianceWords.InterlockedCompareExchange(address, expected, asuint(asfloat(expected) + value), original);
        stored = original == expected;
        expected = original;
    }
    return stored;
}
#endif
#endif

#if defined(CAUSTICS_FIXED_POINT) || defined(CAUSTICS_FIXED_POINT_64)
// The largest scaled value one add takes before it saturates the word by itself: under 2^32 = 4.29e9
// (exactly representable as a uint), float(2^64) = 1.8447e19.
#if defined(CAUSTICS_FIXED_POINT_64)
CAUSTICS_CONST float kRadianceSaturation = 1.8e19f;
#else
CAUSTICS_CONST float kRadianceSaturation = 4.0e9f;
#endif
// PCG output permutation (O'Neill 2014) used as an integer hash.
uint radianceHash(uint x) {
    uint state = x * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}
// Uniform in [0, 1), different per launch, pixel, channel and value: the rounding decisions of
// different adds are independent, so the rounded sum's expectation is the exact sum.
float radianceDither(uint pixel, uint c, float v) {
    uint3 id = RADIANCE_LAUNCH_ID;
    uint launch = id.x + 0x9E3779B9u * (id.y + 0x85EBCA6Bu * id.z);
    uint h = radianceHash(pixel ^ radianceHash(asuint(v) ^ radianceHash(launch * 3u + c)));
    return float(h >> 8u) * (1.0f / 16777216.0f);
}

void addRadiance(uint pixel, float3 value) {
    const float scale = asfloat(statsLoad(kStatFixedPointScale));
    for (uint c = 0u; c < 3u; ++c) {
        float s = value[c] * scale;
        if (!(s > 0.0f)) continue;
        const uint word = 3u * pixel + c;
        bool saturated = s >= kRadianceSaturation;
        float whole = floor(min(s, kRadianceSaturation));
        RadianceWord add = RadianceWord(whole) + ((s - whole) > radianceDither(pixel, c, value[c]) ? RadianceWord(1u) : RadianceWord(0u));
        if (add == RadianceWord(0u)) continue;
        RadianceWord old = radianceWordAdd(word, add);
        // The sum wrapped past the word's maximum: pin it there; a later add that wraps again pins it
        // again, so the word ends saturated whatever the order of the threads.
        if (saturated || old > RADIANCE_WORD_MAX - add) {
            radianceWordPin(word);
            statsAtomicAdd(kStatSaturatedAdds, 1u);
        }
    }
}
#else
void addRadiance(uint pixel, float3 value) {
    for (uint c = 0u; c < 3u; ++c) {
        if (!(value[c] > 0.0f)) continue;
        if (!radianceFloatAdd(3u * pixel + c, value[c])) statsAtomicAdd(kStatAccumulationGiveUps, 1u);
    }
}
#endif
#endif  // CAUSTICS_COMMON_RADIANCE_ATOMICS_H
