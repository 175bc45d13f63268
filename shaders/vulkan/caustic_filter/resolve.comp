#version 460
// Radiance buffers -> RGBA32F textures: first type, second type and their sum; or, with one buffer for
// both types (kCombinedOnly), the sum alone. Words: float bits, or fixed point (kFixedPoint: value x
// scale, pc.invScale = 1 / scale, docs/caustics.md "Fixed point") in one uint per channel or, with
// kWide, one uint64 per channel (lo, hi words).
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, std430) readonly buffer First { uint firstWords[]; };
layout(set = 0, binding = 1, std430) readonly buffer Second { uint secondWords[]; };
layout(set = 0, binding = 2, rgba32f) uniform writeonly image2D outFirst;
layout(set = 0, binding = 3, rgba32f) uniform writeonly image2D outSecond;
layout(set = 0, binding = 4, rgba32f) uniform writeonly image2D outCombined;
layout(push_constant) uniform Push { uint width; uint height; uint flags; float invScale; } pc;
const uint kFixedPoint = 1u, kCombinedOnly = 2u, kWide = 4u;

float wide(uint lo, uint hi) { return float(hi) * 4294967296.0 + float(lo); }

vec3 decode(uint a, uint b, uint c) {
    if ((pc.flags & kFixedPoint) != 0u) return vec3(a, b, c) * pc.invScale;
    return vec3(uintBitsToFloat(a), uintBitsToFloat(b), uintBitsToFloat(c));
}
vec3 loadFirst(uint pixel) {
    if ((pc.flags & kWide) != 0u) {
        uint i = 6u * pixel;
        return vec3(wide(firstWords[i], firstWords[i + 1u]), wide(firstWords[i + 2u], firstWords[i + 3u]),
                    wide(firstWords[i + 4u], firstWords[i + 5u])) * pc.invScale;
    }
    uint i = 3u * pixel;
    return decode(firstWords[i], firstWords[i + 1u], firstWords[i + 2u]);
}
vec3 loadSecond(uint pixel) {
    if ((pc.flags & kWide) != 0u) {
        uint i = 6u * pixel;
        return vec3(wide(secondWords[i], secondWords[i + 1u]), wide(secondWords[i + 2u], secondWords[i + 3u]),
                    wide(secondWords[i + 4u], secondWords[i + 5u])) * pc.invScale;
    }
    uint i = 3u * pixel;
    return decode(secondWords[i], secondWords[i + 1u], secondWords[i + 2u]);
}
void main() {
    uvec2 p = gl_GlobalInvocationID.xy;
    if (p.x >= pc.width || p.y >= pc.height) return;
    uint pixel = p.y * pc.width + p.x;
    vec3 a = loadFirst(pixel);
    if ((pc.flags & kCombinedOnly) != 0u) {
        imageStore(outCombined, ivec2(p), vec4(a, 1.0));
        return;
    }
    vec3 b = loadSecond(pixel);
    imageStore(outFirst, ivec2(p), vec4(a, 1.0));
    imageStore(outSecond, ivec2(p), vec4(b, 1.0));
    imageStore(outCombined, ivec2(p), vec4(a + b, 1.0));
}
