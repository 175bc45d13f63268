// First half of one a-trous iteration (mirror of shaders/vulkan/caustic_filter/atrous_weights.comp,
// which explains the energy-preserving normalisation): per source pixel q, W_q = sum of the weights
// with which it spreads to its 5x5 holed neighbourhood, from this frame's packed guides. Over the
// listed tiles; pixels of unlisted tiles receive nothing and are left out of W_q.
#include "caustic_filter/filter_common.hlsli"
Texture2D<float4> inColor : register(t0, space0);   // rgb radiance, a luminance variance
Texture2D<uint4> guides : register(t1, space0);
RWTexture2D<float> outSource : register(u2, space0);   // W
ByteAddressBuffer tiles : register(t3, space0);
Texture2D<uint> tileState : register(t4, space0);   // 0: a tile no filter pass wrote this frame
struct Push { int stepWidth; int width; int height; float sigmaLuminance; };
ConstantBuffer<Push> pc : register(b0, space999);

[numthreads(8, 8, 1)]
void main(uint3 group : SV_GroupID, uint3 groupThread : SV_GroupThreadID) {
    int2 q = filterTilePixel(tiles.Load(4u * group.x), groupThread.xy);
    if (q.x >= pc.width || q.y >= pc.height) return;
    FilterGuide gq = filterUnpackGuide(guides.Load(int3(q, 0)));
    if (gq.id == 0u) { outSource[q] = 1.0f; return; }
    float4 c = inColor.Load(int3(q, 0));
    float total = 0.0f;
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            int2 offset = int2(dx, dy) * pc.stepWidth;
            int2 p = q + offset;
            if (p.x < 0 || p.y < 0 || p.x >= pc.width || p.y >= pc.height) continue;
            if (tileState.Load(int3(p / kFilterTileSize, 0)) == 0u) continue;
            FilterGuide gp = filterUnpackGuide(guides.Load(int3(p, 0)));
            if (gp.id != gq.id) continue;
            float4 cp = inColor.Load(int3(p, 0));
            total += filterSpreadWeight(offset, pc.stepWidth, gq.depth, gp.depth, gq.gradZ, gq.normal, gp.normal,
                                        filterLuminance(c.rgb), filterLuminance(cp.rgb), c.a, cp.a, pc.sigmaLuminance);
        }
    }
    outSource[q] = total;
}
