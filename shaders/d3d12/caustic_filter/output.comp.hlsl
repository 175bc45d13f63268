// With no a-trous iteration the temporal result is the module's radiance, copied over the listed tiles
// only (mirror of shaders/vulkan/caustic_filter/output.comp).
#include "caustic_filter/filter_common.hlsli"
Texture2D<float4> temporalColor : register(t0, space0);
ByteAddressBuffer tiles : register(t1, space0);
RWTexture2D<float4> outColor : register(u2, space0);
struct Push { int width; int height; };
ConstantBuffer<Push> pc : register(b0, space999);

[numthreads(8, 8, 1)]
void main(uint3 group : SV_GroupID, uint3 groupThread : SV_GroupThreadID) {
    int2 p = filterTilePixel(tiles.Load(4u * group.x), groupThread.xy);
    if (p.x >= pc.width || p.y >= pc.height) return;
    outColor[p] = float4(temporalColor.Load(int3(p, 0)).rgb, 1.0f);
}
