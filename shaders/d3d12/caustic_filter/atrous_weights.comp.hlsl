// First half of one a-trous iteration (mirror of shaders/vulkan/caustic_filter/atrous_weights.comp,
// which explains the energy-preserving normalisation): per source pixel q, W_q = sum of the weights
// with which it spreads to its 5x5 holed neighbourhood, and its screen-space depth gradient. Over the
// listed tiles; pixels of unlisted tiles receive nothing and are left out of W_q.
#include "caustic_filter/filter_common.hlsli"
Texture2D<float4> inColor : register(t0, space0);   // rgb radiance, a luminance variance
Texture2D<float4> gLinearDepth : register(t1, space0);
Texture2D<float4> gNormal : register(t2, space0);
Texture2D<uint> gObjectId : register(t3, space0);
RWTexture2D<float4> outSource : register(u4, space0);   // W, dz/dx, dz/dy, 0
ByteAddressBuffer tiles : register(t5, space0);
Texture2D<uint> tileState : register(t6, space0);   // 0: a tile no filter pass wrote this frame
struct Push { int stepWidth; int width; int height; float sigmaLuminance; };
ConstantBuffer<Push> pc : register(b0, space999);

bool sameSurface(int2 q, uint objectId) {
    return q.x >= 0 && q.y >= 0 && q.x < pc.width && q.y < pc.height && gObjectId.Load(int3(q, 0)) == objectId;
}

// Smaller one-sided difference of linear depth along `axis` (no leniency across a depth edge).
float depthSlope(int2 p, int2 axis, float z, uint objectId) {
    float slope = 3.0e38f;
    if (sameSurface(p + axis, objectId)) slope = gLinearDepth.Load(int3(p + axis, 0)).r - z;
    if (sameSurface(p - axis, objectId)) {
        float back = z - gLinearDepth.Load(int3(p - axis, 0)).r;
        if (abs(back) < abs(slope)) slope = back;
    }
    return slope < 3.0e38f ? slope : 0.0f;
}

[numthreads(8, 8, 1)]
void main(uint3 group : SV_GroupID, uint3 groupThread : SV_GroupThreadID) {
    int2 q = filterTilePixel(tiles.Load(4u * group.x), groupThread.xy);
    if (q.x >= pc.width || q.y >= pc.height) return;
    uint objectId = gObjectId.Load(int3(q, 0));
    if (objectId == 0u) { outSource[q] = float4(1.0f, 0.0f, 0.0f, 0.0f); return; }
    float z = gLinearDepth.Load(int3(q, 0)).r;
    float3 n = gNormal.Load(int3(q, 0)).xyz;
    float4 c = inColor.Load(int3(q, 0));
    float2 gradZ = float2(depthSlope(q, int2(1, 0), z, objectId), depthSlope(q, int2(0, 1), z, objectId));
    float total = 0.0f;
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            int2 offset = int2(dx, dy) * pc.stepWidth;
            int2 p = q + offset;
            if (!sameSurface(p, objectId) || tileState.Load(int3(p / kFilterTileSize, 0)) == 0u) continue;
            float4 cp = inColor.Load(int3(p, 0));
            total += filterSpreadWeight(offset, pc.stepWidth, z, gLinearDepth.Load(int3(p, 0)).r, gradZ, n,
                                        gNormal.Load(int3(p, 0)).xyz, filterLuminance(c.rgb),
                                        filterLuminance(cp.rgb), c.a, cp.a, pc.sigmaLuminance);
        }
    }
    outSource[q] = float4(total, gradZ, 0.0f);
}
