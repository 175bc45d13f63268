#ifndef CAUSTICS_D3D12_RADIANCE_ATOMICS_HLSLI
#define CAUSTICS_D3D12_RADIANCE_ATOMICS_HLSLI
// Atomic RGB radiance per pixel, 3 words per pixel (mirror of shaders/vulkan/forward_trace/
// radiance_atomics.glsl). Define RADIANCE_REGISTER (e.g. u5) and RADIANCE_SPACE, and declare the
// `RWByteAddressBuffer stats` of caustic_hit.hlsli, first.
// HLSL has no float atomic add (SM 6.6 adds only 64-bit integer atomics and bitwise float
// compare-exchange), so the float variant is a compare-exchange loop on the float's bits: the buffer
// holds the same float bits as the Vulkan float-atomic variant. CAUSTICS_FIXED_POINT: round(v x 65536)
// added as uint (caustics::kFixedPointScale; saturating), as on Vulkan.
RWByteAddressBuffer radianceWords : register(RADIANCE_REGISTER, RADIANCE_SPACE);

#ifdef CAUSTICS_FIXED_POINT
void addRadiance(uint pixel, float3 value) {
    for (uint c = 0u; c < 3u; ++c) {
        float v = clamp(value[c] * 65536.0f + 0.5f, 0.0f, 4.0e9f);
        if (v < 1.0f) continue;
        uint add = uint(v);
        uint old;
        radianceWords.InterlockedAdd(4u * (3u * pixel + c), add, old);
        // Wrapped past 2^32: pin at the maximum (as the GLSL does; any later wrap pins it again).
        if (old > 0xFFFFFFFFu - add) radianceWords.InterlockedMax(4u * (3u * pixel + c), 0xFFFFFFFFu);
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
