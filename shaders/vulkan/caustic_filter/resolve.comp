#version 460
// Radiance buffers (3 words per pixel; float bits or fixed point x 65536) -> RGBA32F textures:
// first type, second type and their sum.
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, std430) readonly buffer First { uint firstWords[]; };
layout(set = 0, binding = 1, std430) readonly buffer Second { uint secondWords[]; };
layout(set = 0, binding = 2, rgba32f) uniform writeonly image2D outFirst;
layout(set = 0, binding = 3, rgba32f) uniform writeonly image2D outSecond;
layout(set = 0, binding = 4, rgba32f) uniform writeonly image2D outCombined;
layout(push_constant) uniform Push { uint width; uint height; uint fixedPoint; uint pad; } pc;

vec3 decode(uint a, uint b, uint c) {
    if (pc.fixedPoint != 0u) return vec3(a, b, c) / 65536.0;
    return vec3(uintBitsToFloat(a), uintBitsToFloat(b), uintBitsToFloat(c));
}
void main() {
    uvec2 p = gl_GlobalInvocationID.xy;
    if (p.x >= pc.width || p.y >= pc.height) return;
    uint i = 3u * (p.y * pc.width + p.x);
    vec3 a = decode(firstWords[i], firstWords[i + 1u], firstWords[i + 2u]);
    vec3 b = decode(secondWords[i], secondWords[i + 1u], secondWords[i + 2u]);
    imageStore(outFirst, ivec2(p), vec4(a, 1.0));
    imageStore(outSecond, ivec2(p), vec4(b, 1.0));
    imageStore(outCombined, ivec2(p), vec4(a + b, 1.0));
}
