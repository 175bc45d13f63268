#ifndef CAUSTICS_RADIANCE_ATOMICS_GLSL
#define CAUSTICS_RADIANCE_ATOMICS_GLSL
// Atomic accumulation of RGB radiance per pixel (3 words per pixel). The authors' code adds with a
// non-atomic += (a data race); here every add is atomic: float atomics (GL_EXT_shader_atomic_float)
// where the device has them, else fixed point: round(value x 65536) into uint (caustics::
// kFixedPointScale; saturates instead of wrapping). Define RADIANCE_SET / RADIANCE_BINDING first.
#ifdef CAUSTICS_FIXED_POINT
layout(set = RADIANCE_SET, binding = RADIANCE_BINDING, std430) buffer RadianceBuffer { uint radianceWords[]; };
void addRadiance(uint pixel, vec3 value) {
    for (uint c = 0u; c < 3u; ++c) {
        float v = clamp(value[c] * 65536.0 + 0.5, 0.0, 4.0e9);
        if (v < 1.0) continue;
        uint add = uint(v);
        uint old = atomicAdd(radianceWords[3u * pixel + c], add);
        // The sum wrapped past 2^32: pin it at the maximum. Any later add that wraps again pins it
        // again, so the word ends saturated whatever the order of the threads.
        if (old > 0xFFFFFFFFu - add) atomicMax(radianceWords[3u * pixel + c], 0xFFFFFFFFu);
    }
}
#else
#extension GL_EXT_shader_atomic_float : require
layout(set = RADIANCE_SET, binding = RADIANCE_BINDING, std430) buffer RadianceBuffer { float radianceWords[]; };
void addRadiance(uint pixel, vec3 value) {
    for (uint c = 0u; c < 3u; ++c) {
        if (value[c] > 0.0) atomicAdd(radianceWords[3u * pixel + c], value[c]);
    }
}
#endif
#endif
