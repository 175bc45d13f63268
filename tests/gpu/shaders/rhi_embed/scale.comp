#version 460
// Reads a host engine's storage buffer and writes value * 3 + 1 into its R32_UINT storage image
// (checked on the CPU by rhi_embed/wrapped_device_test.cpp).
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, std430) readonly buffer In { uint values[]; };
layout(set = 0, binding = 1, r32ui) uniform writeonly uimage2D image;
layout(push_constant) uniform Push { uint width; uint height; } pc;

void main() {
    uvec2 p = gl_GlobalInvocationID.xy;
    if (p.x >= pc.width || p.y >= pc.height) return;
    imageStore(image, ivec2(p), uvec4(values[p.y * pc.width + p.x] * 3u + 1u, 0u, 0u, 0u));
}
