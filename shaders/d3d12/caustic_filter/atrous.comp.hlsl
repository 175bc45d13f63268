// Second half of one a-trous iteration (mirror of shaders/vulkan/caustic_filter/atrous.comp): pixel p
// receives from each source q of its 5x5 holed neighbourhood the share w(q -> p) / W_q of q's
// radiance; the variance goes along as sum (w / W_q)^2 Var_q. Over the listed tiles; sources in
// unlisted tiles are skipped.
#include "caustic_filter/filter_common.hlsli"
Texture2D<float4> inColor : register(t0, space0);   // rgb radiance, a luminance variance
Texture2D<float4> sources : register(t1, space0);   // W per source
Texture2D<uint4> guides : register(t2, space0);
RWTexture2D<float4> outColor : register(u3, space0);
ByteAddressBuffer tiles : register(t4, space0);
Texture2D<uint> tileState : register(t5, space0);   // 0: a tile no filter pass wrote this frame
struct Push { int stepWidth; int width; int height; float sigmaLuminance; uint lastIteration; };
ConstantBuffer<Push> pc : register(b0, space999);

[numthreads(8, 8, 1)]
void main(uint3 group : SV_GroupID, uint3 groupThread : SV_GroupThreadID) {
    int2 p = filterTilePixel(tiles.Load(4u * group.x), groupThread.xy);
    if (p.x >= pc.width || p.y >= pc.height) return;
    float4 centre = inColor.Load(int3(p, 0));
    FilterGuide gp = filterUnpackGuide(guides.Load(int3(p, 0)));
    if (gp.id == 0u) {
        outColor[p] = float4(centre.rgb, pc.lastIteration != 0u ? 1.0f : centre.a);
        return;
    }
    float lp = filterLuminance(centre.rgb);
    float3 sum = (float3)0.0f;
    float variance = 0.0f;
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            int2 q = p + int2(dx, dy) * pc.stepWidth;
            if (q.x < 0 || q.y < 0 || q.x >= pc.width || q.y >= pc.height) continue;
            if (tileState.Load(int3(q / kFilterTileSize, 0)) == 0u) continue;
            FilterGuide gq = filterUnpackGuide(guides.Load(int3(q, 0)));
            if (gq.id != gp.id) continue;
            float4 c = inColor.Load(int3(q, 0));
            float share = filterSpreadWeight(p - q, pc.stepWidth, gq.depth, gp.depth, gq.gradZ, gq.normal, gp.normal,
                                             filterLuminance(c.rgb), lp, c.a, centre.a, pc.sigmaLuminance) /
                          sources.Load(int3(q, 0)).r;
            sum += share * c.rgb;
            variance += share * share * c.a;
        }
    }
    outColor[p] = float4(sum, pc.lastIteration != 0u ? 1.0f : variance);
}
