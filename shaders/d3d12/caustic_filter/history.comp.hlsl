// Keeps this frame's temporal accumulation (unfiltered, so the history stays an unbiased average), its
// luminance moments and history length, and the G-buffer guides of the next frame's disocclusion test
// (mirror of shaders/vulkan/caustic_filter/history.comp), over the listed tiles only.
#include "caustic_filter/filter_common.hlsli"
Texture2D<float4> temporalColor : register(t0, space0);
Texture2D<float4> temporalMoments : register(t1, space0);
Texture2D<float4> gLinearDepth : register(t2, space0);
Texture2D<float4> gNormal : register(t3, space0);
Texture2D<uint> gObjectId : register(t4, space0);
RWTexture2D<float4> historyColor : register(u5, space0);
RWTexture2D<float4> historyMoments : register(u6, space0);
RWTexture2D<float> historyDepth : register(u7, space0);
RWTexture2D<float4> historyNormal : register(u8, space0);
RWTexture2D<uint> historyObjectId : register(u9, space0);
ByteAddressBuffer tiles : register(t10, space0);
struct Push { int width; int height; };
ConstantBuffer<Push> pc : register(b0, space999);

[numthreads(8, 8, 1)]
void main(uint3 group : SV_GroupID, uint3 groupThread : SV_GroupThreadID) {
    int2 p = filterTilePixel(tiles.Load(4u * group.x), groupThread.xy);
    if (p.x >= pc.width || p.y >= pc.height) return;
    historyColor[p] = temporalColor.Load(int3(p, 0));
    historyMoments[p] = temporalMoments.Load(int3(p, 0));
    historyDepth[p] = gLinearDepth.Load(int3(p, 0)).r;
    historyNormal[p] = gNormal.Load(int3(p, 0));
    historyObjectId[p] = gObjectId.Load(int3(p, 0));
}
