// One edge-aware a-trous iteration (Dammertz et al. 2010; mirror of shaders/vulkan/caustic_filter/
// atrous.comp): 5x5 B3-spline kernel with holes of stepWidth, weighted by normal, depth and object id.
Texture2D<float4> inColor : register(t0, space0);
Texture2D<float4> gLinearDepth : register(t1, space0);
Texture2D<float4> gNormal : register(t2, space0);
Texture2D<uint> gObjectId : register(t3, space0);
RWTexture2D<float4> outColor : register(u4, space0);
struct Push { int stepWidth; int width; int height; int pad; };
ConstantBuffer<Push> pc : register(b0, space999);

static const float kKernel[3] = {3.0f / 8.0f, 1.0f / 4.0f, 1.0f / 16.0f};

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    int2 p = int2(id.xy);
    if (p.x >= pc.width || p.y >= pc.height) return;
    float4 centre = inColor.Load(int3(p, 0));
    float z = gLinearDepth.Load(int3(p, 0)).r;
    float3 n = gNormal.Load(int3(p, 0)).xyz;
    uint objectId = gObjectId.Load(int3(p, 0));
    if (objectId == 0u) { outColor[p] = centre; return; }
    float3 sum = (float3)0.0f;
    float weights = 0.0f;
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            int2 q = p + int2(dx, dy) * pc.stepWidth;
            if (q.x < 0 || q.y < 0 || q.x >= pc.width || q.y >= pc.height) continue;
            if (gObjectId.Load(int3(q, 0)) != objectId) continue;
            float zq = gLinearDepth.Load(int3(q, 0)).r;
            float wz = exp(-abs(zq - z) / (0.01f * z * float(pc.stepWidth) * length(float2(dx, dy)) + 1e-6f));
            float wn = pow(max(0.0f, dot(n, gNormal.Load(int3(q, 0)).xyz)), 64.0f);
            float w = kKernel[abs(dx)] * kKernel[abs(dy)] * wz * wn;
            sum += w * inColor.Load(int3(q, 0)).rgb;
            weights += w;
        }
    }
    outColor[p] = float4(weights > 0.0f ? sum / weights : centre.rgb, 1.0f);
}
