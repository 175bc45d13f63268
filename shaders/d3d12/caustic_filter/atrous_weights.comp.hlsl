// First half of one a-trous iteration (mirror of shaders/vulkan/caustic_filter/atrous_weights.comp):
// W_q, the sum of the weights with which source q spreads to its 5x5 holed neighbourhood, from this
// frame's G-buffer and the depth gradient. Over the listed tiles; pixels without a pool tile are left out.
#include "caustic_filter/filter_common.hlsli"
Texture2D<float4> inColor : register(t0, space0);   // pool: rgb radiance, a deviation of the mean
Texture2D<float4> gLinearDepth : register(t1, space0);
Texture2D<float4> gNormal : register(t2, space0);
Texture2D<uint> gObjectId : register(t3, space0);
Texture2D<uint> gradient : register(t4, space0);    // pool: half2 depth slope
Texture2D<uint> slotMap : register(t5, space0);
ByteAddressBuffer tiles : register(t6, space0);
RWTexture2D<float> outSource : register(u7, space0);   // pool: W
struct Push { int stepWidth; int width; int height; float sigmaLuminance; };
ConstantBuffer<Push> pc : register(b0, space999);

[numthreads(8, 8, 1)]
void main(uint3 group : SV_GroupID, uint3 groupThread : SV_GroupThreadID) {
    int2 q = filterTilePixel(tiles.Load(4u * group.x), groupThread.xy);
    if (q.x >= pc.width || q.y >= pc.height) return;
    int2 own = filterPoolTexel(group.x, int2(groupThread.xy));
    uint objectId = gObjectId.Load(int3(q, 0));
    if (objectId == 0u) { outSource[own] = 1.0f; return; }
    float4 c = inColor.Load(int3(own, 0));
    float zq = gLinearDepth.Load(int3(q, 0)).r;
    float3 nq = gNormal.Load(int3(q, 0)).xyz;
    float2 gradZq = filterUnpackHalf2(gradient.Load(int3(own, 0)));
    float total = 0.0f;
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            int2 offset = int2(dx, dy) * pc.stepWidth;
            int2 p = q + offset;
            if (p.x < 0 || p.y < 0 || p.x >= pc.width || p.y >= pc.height) continue;
            uint slot = slotMap.Load(int3(p / kFilterTileSize, 0));
            if (slot == kFilterNoSlot) continue;
            if (gObjectId.Load(int3(p, 0)) != objectId) continue;
            float4 cp = inColor.Load(int3(filterPoolTexel(slot, filterLocal(p)), 0));
            total += filterSpreadWeight(offset, pc.stepWidth, zq, gLinearDepth.Load(int3(p, 0)).r, gradZq, nq,
                                        gNormal.Load(int3(p, 0)).xyz, filterLuminance(c.rgb), filterLuminance(cp.rgb),
                                        c.a * c.a, cp.a * cp.a, pc.sigmaLuminance);
        }
    }
    outSource[own] = total;
}
