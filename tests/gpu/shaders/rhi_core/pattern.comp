#version 460
// Writes a closed-form pattern into a storage buffer and an R32_UINT storage image
// (checked on the CPU by rhi_core/compute_pattern_test.cpp).
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, std430) buffer Out { uint values[]; };
layout(set = 0, binding = 1, r32ui) uniform writeonly uimage2D image;
layout(push_constant) uniform Push { uint width; uint height; uint seed; } pc;

void main() {
    uvec2 p = gl_GlobalInvocationID.xy;
    if (p.x >= pc.width || p.y >= pc.height) return;
    uint i = p.y * pc.width + p.x;
    values[i] = (i * 2654435761u) ^ pc.seed;
    imageStore(image, ivec2(p), uvec4(p.x * 1000u + p.y + pc.seed, 0u, 0u, 0u));
}
