// Variance of the accumulated luminance for the a-trous luminance edge-stopping (mirror of
// shaders/vulkan/caustic_filter/variance.comp, which explains the model): temporal moments with 4 or
// more frames of history, else photon shot noise q l (q: smallest non-zero luminance of this frame in
// the 7x7 window, l: the pixel's accumulated luminance). Alpha: variance of the mean.
#include "caustic_filter/filter_common.hlsli"
Texture2D<float4> current : register(t0, space0);
Texture2D<float4> temporalColor : register(t1, space0);
Texture2D<float4> temporalMoments : register(t2, space0);
Texture2D<uint> gObjectId : register(t3, space0);
RWTexture2D<float4> outColor : register(u4, space0);
struct Push { int width; int height; };
ConstantBuffer<Push> pc : register(b0, space999);

static const float kTemporalHistory = 4.0f;

[numthreads(8, 8, 1)]
void main(uint3 tid : SV_DispatchThreadID) {
    int2 p = int2(tid.xy);
    if (p.x >= pc.width || p.y >= pc.height) return;
    float3 accumulated = temporalColor.Load(int3(p, 0)).rgb;
    float3 moments = temporalMoments.Load(int3(p, 0)).xyz;
    uint objectId = gObjectId.Load(int3(p, 0));
    float n = max(moments.z, 1.0f);
    float variance = 0.0f;
    if (objectId != 0u && n >= kTemporalHistory) {
        variance = max(0.0f, moments.y - moments.x * moments.x);
    } else if (objectId != 0u) {
        float quantum = 3.0e38f;
        for (int dy = -3; dy <= 3; ++dy) {
            for (int dx = -3; dx <= 3; ++dx) {
                int2 q = p + int2(dx, dy);
                if (q.x < 0 || q.y < 0 || q.x >= pc.width || q.y >= pc.height) continue;
                if (gObjectId.Load(int3(q, 0)) != objectId) continue;
                float l = filterLuminance(current.Load(int3(q, 0)).rgb);
                if (l > 0.0f) quantum = min(quantum, l);
            }
        }
        if (quantum < 3.0e38f) variance = quantum * filterLuminance(accumulated);
    }
    outColor[p] = float4(accumulated, variance / n);
}
