#ifndef CAUSTICS_RADIANCE_ATOMICS_GLSL
#define CAUSTICS_RADIANCE_ATOMICS_GLSL
// Atomic accumulation of RGB radiance per pixel. The authors' code adds with a non-atomic += (a data
// race); here every add is atomic: float atomics (GL_EXT_shader_atomic_float) where the device has
// them, else fixed point (docs/caustics.md, "Fixed point"): value x scale, the scale being 2^16 (narrow
// words, one uint per channel) or 2^32 (CAUSTICS_FIXED_POINT_64: one uint64 per channel, where the device
// has shaderBufferInt64Atomics) times the frame's pre-exposure, written by the host into
// stats[kStatFixedPointScale]. Sub-LSB parts round stochastically (up with probability equal to the
// fraction), so faint light adds up unbiased instead of vanishing; a sum that would pass the word's
// maximum pins there and is counted (stats[kStatSaturatedAdds], causticStatsWarnings).
// Define RADIANCE_SET / RADIANCE_BINDING (or RADIANCE_DECLARED where the pass's generated bindings declare
// radianceWords) and declare `uint stats[]` (common/caustic_stats.h slots) first.
#if defined(CAUSTICS_FIXED_POINT) || defined(CAUSTICS_FIXED_POINT_64)
// PCG output permutation (O'Neill 2014) used as an integer hash.
uint radianceHash(uint x) {
    uint state = x * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}
// Uniform in [0, 1), different per launch, pixel, channel and value: the rounding decisions of
// different adds are independent, so the rounded sum's expectation is the exact sum.
float radianceDither(uint pixel, uint c, float v) {
    uint launch = gl_LaunchIDEXT.x + 0x9E3779B9u * (gl_LaunchIDEXT.y + 0x85EBCA6Bu * gl_LaunchIDEXT.z);
    uint h = radianceHash(pixel ^ radianceHash(floatBitsToUint(v) ^ radianceHash(launch * 3u + c)));
    return float(h >> 8u) * (1.0 / 16777216.0);
}
float radianceFixedPointScale() { return uintBitsToFloat(stats[kStatFixedPointScale]); }
#endif

#if defined(CAUSTICS_FIXED_POINT_64)
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#ifndef RADIANCE_DECLARED
layout(set = RADIANCE_SET, binding = RADIANCE_BINDING, std430) buffer RadianceBuffer { uint64_t radianceWords[]; };
#endif
void addRadiance(uint pixel, vec3 value) {
    const float scale = radianceFixedPointScale();
    for (uint c = 0u; c < 3u; ++c) {
        float s = value[c] * scale;
        if (!(s > 0.0)) continue;
        const uint word = 3u * pixel + c;
        // float(2^64) = 1.8447e19: a single add that large saturates the word by itself.
        bool saturated = s >= 1.8e19;
        float whole = floor(min(s, 1.8e19));
        uint64_t add = uint64_t(whole) + ((s - whole) > radianceDither(pixel, c, value[c]) ? 1ul : 0ul);
        if (add == 0ul) continue;
        uint64_t old = atomicAdd(radianceWords[word], add);
        // The sum wrapped past 2^64: pin it at the maximum; a later add that wraps again pins it again,
        // so the word ends saturated whatever the order of the threads.
        if (saturated || old > 0xFFFFFFFFFFFFFFFFul - add) {
            atomicMax(radianceWords[word], 0xFFFFFFFFFFFFFFFFul);
            atomicAdd(stats[kStatSaturatedAdds], 1u);
        }
    }
}
#elif defined(CAUSTICS_FIXED_POINT)
#ifndef RADIANCE_DECLARED
layout(set = RADIANCE_SET, binding = RADIANCE_BINDING, std430) buffer RadianceBuffer { uint radianceWords[]; };
#endif
void addRadiance(uint pixel, vec3 value) {
    const float scale = radianceFixedPointScale();
    for (uint c = 0u; c < 3u; ++c) {
        float s = value[c] * scale;
        if (!(s > 0.0)) continue;
        const uint word = 3u * pixel + c;
        bool saturated = s >= 4.0e9;   // under 2^32 = 4.29e9, exactly representable as a uint
        float whole = floor(min(s, 4.0e9));
        uint add = uint(whole) + ((s - whole) > radianceDither(pixel, c, value[c]) ? 1u : 0u);
        if (add == 0u) continue;
        uint old = atomicAdd(radianceWords[word], add);
        if (saturated || old > 0xFFFFFFFFu - add) {
            atomicMax(radianceWords[word], 0xFFFFFFFFu);
            atomicAdd(stats[kStatSaturatedAdds], 1u);
        }
    }
}
#else
#extension GL_EXT_shader_atomic_float : require
#ifndef RADIANCE_DECLARED
layout(set = RADIANCE_SET, binding = RADIANCE_BINDING, std430) buffer RadianceBuffer { float radianceWords[]; };
#endif
void addRadiance(uint pixel, vec3 value) {
    for (uint c = 0u; c < 3u; ++c) {
        if (value[c] > 0.0) atomicAdd(radianceWords[3u * pixel + c], value[c]);
    }
}
#endif
#endif
