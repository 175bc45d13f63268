// With no a-trous iteration the temporal result is the module's radiance, written over the listed tiles
// only (mirror of shaders/vulkan/caustic_filter/output.comp: a pixel without history keeps this frame's
// radiance as it is).
#include "caustic_filter/filter_common.hlsli"
Texture2D<float4> temporalColor : register(t0, space0);   // pool
Texture2D<uint2> temporalGuides : register(t1, space0);   // pool: n
ByteAddressBuffer tiles : register(t2, space0);
RWTexture2D<float4> radiance : register(u3, space0);
struct Push { int width; int height; float invPreExposure; };
ConstantBuffer<Push> pc : register(b0, space999);

[numthreads(8, 8, 1)]
void main(uint3 group : SV_GroupID, uint3 groupThread : SV_GroupThreadID) {
    int2 p = filterTilePixel(tiles.Load(4u * group.x), groupThread.xy);
    if (p.x >= pc.width || p.y >= pc.height) return;
    int2 own = filterPoolTexel(group.x, int2(groupThread.xy));
    if (filterUnpackGuide(temporalGuides.Load(int3(own, 0))).historyLength <= 1.0f) return;
    radiance[p] = float4(temporalColor.Load(int3(own, 0)).rgb * pc.invPreExposure, 1.0f);
}
