// Temporal accumulation with reprojection (paper 3.4; mirror of shaders/vulkan/caustic_filter/
// temporal.comp). prevViewProj is Vulkan's clip (y down) and is used as such: no rasterizer here.
#include "scene/camera.hlsli"
struct CameraBlock { CameraConstants camera; };
ConstantBuffer<CameraBlock> cameraBlock : register(b0, space0);
Texture2D<float4> current : register(t1, space0);
Texture2D<float4> gLinearDepth : register(t2, space0);
Texture2D<float4> gNormal : register(t3, space0);
Texture2D<uint> gObjectId : register(t4, space0);
Texture2D<float4> historyColor : register(t5, space0);
Texture2D<float4> historyDepth : register(t6, space0);
Texture2D<float4> historyNormal : register(t7, space0);
Texture2D<uint> historyObjectId : register(t8, space0);
RWTexture2D<float4> outColor : register(u9, space0);
struct Push { float alpha; uint historyValid; };
ConstantBuffer<Push> pc : register(b0, space999);

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    CameraConstants camera = cameraBlock.camera;
    int2 p = int2(id.xy);
    int2 size = int2(camera.frame.xy);
    if (p.x >= size.x || p.y >= size.y) return;
    float4 cur = current.Load(int3(p, 0));
    float depth = gLinearDepth.Load(int3(p, 0)).r;
    uint objectId = gObjectId.Load(int3(p, 0));
    float4 result = cur;
    if (pc.historyValid != 0u && objectId != 0u && depth > 0.0f) {
        float3 world = cameraWorldPosition(camera, float2(p) + 0.5f, depth);
        float4 clip = mul(camera.prevViewProj, float4(world, 1.0f));
        if (clip.w > 0.0f) {
            float2 prev = (clip.xy / clip.w * 0.5f + 0.5f) * float2(size);
            int2 q = int2(floor(prev));
            if (all(q >= int2(0, 0)) && all(q < size)) {
                bool sameObject = historyObjectId.Load(int3(q, 0)) == objectId;
                bool depthOk = abs(historyDepth.Load(int3(q, 0)).r - clip.w) <= 0.02f * clip.w;
                bool normalOk = dot(historyNormal.Load(int3(q, 0)).xyz, gNormal.Load(int3(p, 0)).xyz) > 0.9f;
                if (sameObject && depthOk && normalOk) result = lerp(historyColor.Load(int3(q, 0)), cur, pc.alpha);
            }
        }
    }
    outColor[p] = result;
}
