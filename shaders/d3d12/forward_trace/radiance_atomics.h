#ifndef CAUSTICS_D3D12_RADIANCE_ATOMICS_HLSLI
#define CAUSTICS_D3D12_RADIANCE_ATOMICS_HLSLI
// Atomic RGB radiance per pixel, 3 words per pixel (mirror of shaders/vulkan/forward_trace/
// radiance_atomics.h). Define RADIANCE_REGISTER (e.g. u5) and RADIANCE_SPACE (or RADIANCE_DECLARED
// where the pass's generated bindings declare radianceWords), and declare `RWByteAddressBuffer stats` first.
// HLSL has no float atomic add (SM 6.6 adds only 64-bit integer atomics and bitwise float
// compare-exchange), so the float variant is a compare-exchange loop on the float's bits: the buffer
// holds the same float bits as the Vulkan float-atomic variant. CAUSTICS_FIXED_POINT (one uint per
// channel) and CAUSTICS_FIXED_POINT_64 (one uint64 per channel, SM 6.6 InterlockedAdd64): value x the
// frame's scale (stats[kStatFixedPointScale]), stochastically rounded, saturating and counted
// (kStatSaturatedAdds), as on Vulkan (docs/caustics.md, "Fixed point").
#ifndef RADIANCE_DECLARED
RWByteAddressBuffer radianceWords : register(RADIANCE_REGISTER, RADIANCE_SPACE);
#endif

#if defined(CAUSTICS_FIXED_POINT) || defined(CAUSTICS_FIXED_POINT_64)
// PCG output permutation (O'Neill 2014) used as an integer hash.
uint radianceHash(uint x) {
    uint state = x * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}
// Uniform in [0, 1), different per launch, pixel, channel and value (independent rounding decisions).
float radianceDither(uint pixel, uint c, float v) {
    uint3 id = DispatchRaysIndex();
    uint launch = id.x + 0x9E3779B9u * (id.y + 0x85EBCA6Bu * id.z);
    uint h = radianceHash(pixel ^ radianceHash(asuint(v) ^ radianceHash(launch * 3u + c)));
    return float(h >> 8u) * (1.0f / 16777216.0f);
}
float radianceFixedPointScale() { return asfloat(stats.Load(4u * kStatFixedPointScale)); }
#endif

#if defined(CAUSTICS_FIXED_POINT_64)
void addRadiance(uint pixel, float3 value) {
    const float scale = radianceFixedPointScale();
    for (uint c = 0u; c < 3u; ++c) {
        float s = value[c] * scale;
        if (!(s > 0.0f)) continue;
        const uint address = 8u * (3u * pixel + c);
        bool saturated = s >= 1.8e19f;   // float(2^64) = 1.8447e19
        float whole = floor(min(s, 1.8e19f));
        uint64_t add = uint64_t(whole) + ((s - whole) > radianceDither(pixel, c, value[c]) ? 1ull : 0ull);
        if (add == 0ull) continue;
        uint64_t old;
        radianceWords.InterlockedAdd64(address, add, old);
        // Wrapped past 2^64: pin at the maximum (any later wrap pins it again), and count it.
        if (saturated || old > 0xFFFFFFFFFFFFFFFFull - add) {
            radianceWords.InterlockedMax64(address, 0xFFFFFFFFFFFFFFFFull);
            stats.InterlockedAdd(4u * kStatSaturatedAdds, 1u);
        }
    }
}
#elif defined(CAUSTICS_FIXED_POINT)
void addRadiance(uint pixel, float3 value) {
    const float scale = radianceFixedPointScale();
    for (uint c = 0u; c < 3u; ++c) {
        float s = value[c] * scale;
        if (!(s > 0.0f)) continue;
        const uint address = 4u * (3u * pixel + c);
        bool saturated = s >= 4.0e9f;   // under 2^32 = 4.29e9
        float whole = floor(min(s, 4.0e9f));
        uint add = uint(whole) + ((s - whole) > radianceDither(pixel, c, value[c]) ? 1u : 0u);
        if (add == 0u) continue;
        uint old;
        radianceWords.InterlockedAdd(address, add, old);
        if (saturated || old > 0xFFFFFFFFu - add) {
            radianceWords.InterlockedMax(address, 0xFFFFFFFFu);
            stats.InterlockedAdd(4u * kStatSaturatedAdds, 1u);
        }
    }
}
#else
void addRadiance(uint pixel, float3 value) {
    for (uint c = 0u; c < 3u; ++c) {
        if (!(value[c] > 0.0f)) continue;
        uint address = 4u * (3u * pixel + c);
        uint expected = radianceWords.Load(address);
        bool stored = false;
        for (uint attempt = 0u; attempt < 1024u && !stored; ++attempt) {   // bounded: no infinite loop under contention
            uint original;
            radianceWords.InterlockedCompareExchange(address, expected, asuint(asfloat(expected) + value[c]), original);
            stored = original == expected;
            expected = original;
        }
        // Never silently: the host reads the count (causticStatsWarnings) and says how many were lost.
        if (!stored) stats.InterlockedAdd(4u * kStatAccumulationGiveUps, 1u);
    }
}
#endif
#endif
