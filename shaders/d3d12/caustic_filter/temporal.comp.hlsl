// Temporal accumulation (SVGF, Schied et al. 2017, section 4.1; mirror of shaders/vulkan/
// caustic_filter/temporal.comp): bilinear history taps that pass the disocclusion test (object id,
// depth, normal), blended with weight 1/n, n = history length capped at maxHistory. prevViewProj is
// Vulkan's clip (y down) and is used as such: no rasterizer here.
#include "scene/camera.hlsli"
#include "caustic_filter/filter_common.hlsli"
struct CameraBlock { CameraConstants camera; };
ConstantBuffer<CameraBlock> cameraBlock : register(b0, space0);
Texture2D<float4> current : register(t1, space0);
Texture2D<float4> gLinearDepth : register(t2, space0);
Texture2D<float4> gNormal : register(t3, space0);
Texture2D<uint> gObjectId : register(t4, space0);
Texture2D<float4> historyColor : register(t5, space0);
Texture2D<float4> historyMoments : register(t6, space0);   // x E[l], y E[l^2], z n
Texture2D<float4> historyDepth : register(t7, space0);
Texture2D<float4> historyNormal : register(t8, space0);
Texture2D<uint> historyObjectId : register(t9, space0);
RWTexture2D<float4> outColor : register(u10, space0);
RWTexture2D<float4> outMoments : register(u11, space0);
struct Push { uint historyValid; float maxHistory; };
ConstantBuffer<Push> pc : register(b0, space999);

[numthreads(8, 8, 1)]
void main(uint3 tid : SV_DispatchThreadID) {
    CameraConstants camera = cameraBlock.camera;
    int2 p = int2(tid.xy);
    int2 size = int2(camera.frame.xy);
    if (p.x >= size.x || p.y >= size.y) return;
    float3 cur = current.Load(int3(p, 0)).rgb;
    float l = filterLuminance(cur);
    float depth = gLinearDepth.Load(int3(p, 0)).r;
    float3 n = gNormal.Load(int3(p, 0)).xyz;
    uint objectId = gObjectId.Load(int3(p, 0));
    float3 color = cur;
    float2 moments = float2(l, l * l);
    float historyLength = 1.0f;
    if (pc.historyValid != 0u && objectId != 0u && depth > 0.0f) {
        float3 world = cameraWorldPosition(camera, float2(p) + 0.5f, depth);
        float4 clip = mul(camera.prevViewProj, float4(world, 1.0f));
        if (clip.w > 0.0f) {
            float2 prev = (clip.xy / clip.w * 0.5f + 0.5f) * float2(size) - 0.5f;   // texel-centre coordinates
            int2 base = int2(floor(prev));
            float2 f = prev - float2(base);
            float tolerance = clip.w * filterRelativeDepthTolerance(camera.forward.w, float(size.y), n,
                                                                   normalize(camera.eye.xyz - world));
            float3 hColor = (float3)0.0f;
            float3 hMoments = (float3)0.0f;
            float wSum = 0.0f;
            for (int i = 0; i < 4; ++i) {
                int2 o = int2(i & 1, i >> 1);
                int2 q = base + o;
                if (any(q < int2(0, 0)) || any(q >= size)) continue;
                if (historyObjectId.Load(int3(q, 0)) != objectId) continue;
                if (abs(historyDepth.Load(int3(q, 0)).r - clip.w) > tolerance) continue;
                if (dot(historyNormal.Load(int3(q, 0)).xyz, n) < 0.9f) continue;
                float w = (o.x == 1 ? f.x : 1.0f - f.x) * (o.y == 1 ? f.y : 1.0f - f.y);
                hColor += w * historyColor.Load(int3(q, 0)).rgb;
                // Per-tap variance, not the moments: mixing the moments of neighbouring texels would add
                // their signal difference to the variance.
                float3 m = historyMoments.Load(int3(q, 0)).xyz;
                hMoments += w * float3(m.x, max(0.0f, m.y - m.x * m.x), m.z);
                wSum += w;
            }
            if (wSum > 0.01f) {
                hColor /= wSum;
                hMoments /= wSum;
                hMoments.y += hMoments.x * hMoments.x;   // back to E[l^2] of the blended history
                historyLength = min(hMoments.z + 1.0f, pc.maxHistory);
                float alpha = 1.0f / historyLength;
                color = lerp(hColor, cur, alpha);
                moments = lerp(hMoments.xy, moments, alpha);
            }
        }
    }
    outColor[p] = float4(color, 1.0f);
    outMoments[p] = float4(moments, historyLength, 0.0f);
}
