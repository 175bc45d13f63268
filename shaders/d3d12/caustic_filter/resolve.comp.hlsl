// Radiance buffers (3 words per pixel; float bits or fixed point x 65536) -> RGBA32F textures
// (mirror of shaders/vulkan/caustic_filter/resolve.comp).
ByteAddressBuffer firstWords : register(t0, space0);
ByteAddressBuffer secondWords : register(t1, space0);
RWTexture2D<float4> outFirst : register(u2, space0);
RWTexture2D<float4> outSecond : register(u3, space0);
RWTexture2D<float4> outCombined : register(u4, space0);
struct Push { uint width; uint height; uint fixedPoint; uint pad; };
ConstantBuffer<Push> pc : register(b0, space999);

float3 decode(uint3 w) {
    if (pc.fixedPoint != 0u) return float3(w) / 65536.0f;
    return asfloat(w);
}

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    uint2 p = id.xy;
    if (p.x >= pc.width || p.y >= pc.height) return;
    uint offset = 12u * (p.y * pc.width + p.x);
    float3 a = decode(firstWords.Load3(offset));
    float3 b = decode(secondWords.Load3(offset));
    outFirst[p] = float4(a, 1.0f);
    outSecond[p] = float4(b, 1.0f);
    outCombined[p] = float4(a + b, 1.0f);
}
