// Second half of one a-trous iteration (mirror of shaders/vulkan/caustic_filter/atrous_body.glsl): pixel
// p receives from each source q of its 5x5 holed neighbourhood the share w(q -> p) / W_q of q's
// radiance; the variance goes along as sum (w / W_q)^2 Var_q (kept as its square root). Over the listed
// tiles; sources without a pool tile are skipped. kAtrousLast: writes caustics.radiance in radiance units.
#include "caustic_filter/filter_common.hlsli"
Texture2D<float4> inColor : register(t0, space0);   // pool
Texture2D<float> sources : register(t1, space0);    // pool: W per source
Texture2D<float4> gLinearDepth : register(t2, space0);
Texture2D<float4> gNormal : register(t3, space0);
Texture2D<uint> gObjectId : register(t4, space0);
Texture2D<uint> gradient : register(t5, space0);    // pool: half2 depth slope
Texture2D<uint> slotMap : register(t6, space0);
ByteAddressBuffer tiles : register(t7, space0);
RWTexture2D<float4> outColor : register(u8, space0);   // pool, or (kAtrousLast) caustics.radiance
struct Push { int stepWidth; int width; int height; float sigmaLuminance; float invPreExposure; };
ConstantBuffer<Push> pc : register(b0, space999);

void store(int2 p, int2 own, float3 rgb, float deviation) {
#if defined(kAtrousLast)
    outColor[p] = float4(rgb * pc.invPreExposure, 1.0f);
#else
    outColor[own] = filterNearestHalf(float4(rgb, deviation));
#endif
}

[numthreads(8, 8, 1)]
void main(uint3 group : SV_GroupID, uint3 groupThread : SV_GroupThreadID) {
    int2 p = filterTilePixel(tiles.Load(4u * group.x), groupThread.xy);
    if (p.x >= pc.width || p.y >= pc.height) return;
    int2 own = filterPoolTexel(group.x, int2(groupThread.xy));
    float4 centre = inColor.Load(int3(own, 0));
    uint objectId = gObjectId.Load(int3(p, 0));
    if (objectId == 0u) {
        store(p, own, centre.rgb, centre.a);
        return;
    }
    float zp = gLinearDepth.Load(int3(p, 0)).r;
    float3 np = gNormal.Load(int3(p, 0)).xyz;
    float lp = filterLuminance(centre.rgb);
    float3 sum = (float3)0.0f;
    float variance = 0.0f;
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            int2 q = p + int2(dx, dy) * pc.stepWidth;
            if (q.x < 0 || q.y < 0 || q.x >= pc.width || q.y >= pc.height) continue;
            uint slot = slotMap.Load(int3(q / kFilterTileSize, 0));
            if (slot == kFilterNoSlot) continue;
            if (gObjectId.Load(int3(q, 0)) != objectId) continue;
            int2 t = filterPoolTexel(slot, filterLocal(q));
            float4 c = inColor.Load(int3(t, 0));
            float2 gradZq = filterUnpackHalf2(gradient.Load(int3(t, 0)));
            float share = filterSpreadWeight(p - q, pc.stepWidth, gLinearDepth.Load(int3(q, 0)).r, zp, gradZq,
                                             gNormal.Load(int3(q, 0)).xyz, np, filterLuminance(c.rgb), lp,
                                             c.a * c.a, centre.a * centre.a, pc.sigmaLuminance) /
                          sources.Load(int3(t, 0));
            sum += share * c.rgb;
            variance += share * share * c.a * c.a;
        }
    }
    store(p, own, sum, sqrt(variance));
}
