// caustics.specularPixels (mirror of shaders/vulkan/backward_trace/specular_pixels.comp): the specular
// camera pixels compacted into a list of pixel indices (cut at the sphere capacity), and the backward pass's indirect grid.
#include "backward_trace/sphere_list.hlsli"

Texture2D<uint> gObjectId : register(t0, space0);
Texture2D<float4> gOptics : register(t1, space0);
RWByteAddressBuffer specularPixels : register(u2, space0);
RWByteAddressBuffer args : register(u3, space0);   // (width, height, depth) of the backward grid
RWByteAddressBuffer stats : register(u4, space0);
struct Push { uint width; uint height; uint sphereCapacity; };
ConstantBuffer<Push> pc : register(b0, space999);

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    uint2 p = id.xy;
    if (all(p == uint2(0u, 0u))) stats.Store(4u * kStatSphereCapacity, pc.sphereCapacity);
    if (p.x >= pc.width || p.y >= pc.height) return;
    if (gObjectId.Load(int3(p, 0)) == 0u || gOptics.Load(int3(p, 0)).w < 0.5f) return;
    // Every specular pixel is counted, only those below the capacity listed (as the GLSL).
    uint slot;
    stats.InterlockedAdd(4u * kStatSpecularPixels, 1u, slot);
    if (slot >= pc.sphereCapacity) return;
    specularPixels.Store(4u * slot, p.y * pc.width + p.x);
    args.InterlockedAdd(0u, 1u);
}
