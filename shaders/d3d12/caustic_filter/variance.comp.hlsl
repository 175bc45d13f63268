// Variance of the accumulated luminance for the a-trous luminance edge-stopping (mirror of
// shaders/vulkan/caustic_filter/variance.comp, which explains the model): temporal moments with 4 or
// more frames of history (max(own, 3x3 mean)), else photon shot noise q l (q: smallest non-zero luminance of this frame in
// the 7x7 window, l: max(own, 3x3 mean) of the accumulated luminance). Output (pool, pre-exposed):
// alpha the deviation of the mean. Over the listed tiles; a neighbour without a pool tile counts as zero.
#include "caustic_filter/filter_common.hlsli"
Texture2D<float4> current : register(t0, space0);
Texture2D<float4> temporalColor : register(t1, space0);    // pool: rgb mean, a per-frame deviation
Texture2D<uint2> temporalGuides : register(t2, space0);    // pool: n
Texture2D<uint> gObjectId : register(t3, space0);
RWTexture2D<float4> outColor : register(u4, space0);       // pool
ByteAddressBuffer tiles : register(t5, space0);
Texture2D<uint> slotMap : register(t6, space0);            // this frame's
struct Push { int width; int height; float preExposure; };
ConstantBuffer<Push> pc : register(b0, space999);

static const float kTemporalHistory = 4.0f;

int2 poolTexel(int2 q) {
    uint slot = slotMap.Load(int3(q / kFilterTileSize, 0));
    return slot == kFilterNoSlot ? int2(-1, -1) : filterPoolTexel(slot, filterLocal(q));
}

float3 momentsAt(int2 t) {
    float4 c = temporalColor.Load(int3(t, 0));
    return float3(filterLuminance(c.rgb), c.a * c.a, filterUnpackGuide(temporalGuides.Load(int3(t, 0))).historyLength);
}

// 3x3 mean of the neighbours' temporal variance on the same object.
float localMeanTemporalVariance(int2 p, uint objectId) {
    float sum = 0.0f, count = 0.0f;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            int2 q = p + int2(dx, dy);
            if (q.x < 0 || q.y < 0 || q.x >= pc.width || q.y >= pc.height) continue;
            if (gObjectId.Load(int3(q, 0)) != objectId) continue;
            int2 t = poolTexel(q);
            if (t.x >= 0) sum += momentsAt(t).y;
            count += 1.0f;
        }
    }
    return sum / max(count, 1.0f);
}

[numthreads(8, 8, 1)]
void main(uint3 group : SV_GroupID, uint3 groupThread : SV_GroupThreadID) {
    int2 p = filterTilePixel(tiles.Load(4u * group.x), groupThread.xy);
    if (p.x >= pc.width || p.y >= pc.height) return;
    int2 own = filterPoolTexel(group.x, int2(groupThread.xy));
    float3 accumulated = temporalColor.Load(int3(own, 0)).rgb;
    float3 moments = momentsAt(own);
    uint objectId = gObjectId.Load(int3(p, 0));
    float n = max(moments.z, 1.0f);
    float variance = 0.0f;
    if (objectId != 0u && n >= kTemporalHistory) {
        variance = max(moments.y, localMeanTemporalVariance(p, objectId));
    } else if (objectId != 0u) {
        float quantum = 3.0e38f;
        float localSum = 0.0f, localCount = 0.0f;
        for (int dy = -3; dy <= 3; ++dy) {
            for (int dx = -3; dx <= 3; ++dx) {
                int2 q = p + int2(dx, dy);
                if (q.x < 0 || q.y < 0 || q.x >= pc.width || q.y >= pc.height) continue;
                if (gObjectId.Load(int3(q, 0)) != objectId) continue;
                float l = filterLuminance(current.Load(int3(q, 0)).rgb * pc.preExposure);
                if (l > 0.0f) quantum = min(quantum, l);
                if (abs(dx) <= 1 && abs(dy) <= 1) {
                    int2 t = poolTexel(q);
                    if (t.x >= 0) localSum += filterLuminance(temporalColor.Load(int3(t, 0)).rgb);
                    localCount += 1.0f;
                }
            }
        }
        float expected = max(filterLuminance(accumulated), localSum / max(localCount, 1.0f));
        if (quantum < 3.0e38f) variance = quantum * expected;
    }
    outColor[own] = filterNearestHalf(float4(accumulated, sqrt(variance / n)));
}
