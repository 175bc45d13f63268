// Radiance buffers -> RGBA32F textures (mirror of shaders/vulkan/caustic_filter/resolve.comp): first
// type, second type and their sum, or the sum alone from one buffer (kCombinedOnly). Words: float bits
// or fixed point (kFixedPoint, x scale; invScale = 1 / scale), one uint per channel or, with kWide, one
// uint64 per channel (lo, hi).
ByteAddressBuffer firstWords : register(t0, space0);
ByteAddressBuffer secondWords : register(t1, space0);
RWTexture2D<float4> outFirst : register(u2, space0);
RWTexture2D<float4> outSecond : register(u3, space0);
RWTexture2D<float4> outCombined : register(u4, space0);
struct Push { uint width; uint height; uint flags; float invScale; };
ConstantBuffer<Push> pc : register(b0, space999);
static const uint kFixedPoint = 1u, kCombinedOnly = 2u, kWide = 4u;

float wide(uint2 w) { return float(w.y) * 4294967296.0f + float(w.x); }

float3 load(ByteAddressBuffer words, uint pixel) {
    if ((pc.flags & kWide) != 0u) {
        uint offset = 24u * pixel;
        return float3(wide(words.Load2(offset)), wide(words.Load2(offset + 8u)), wide(words.Load2(offset + 16u))) *
               pc.invScale;
    }
    uint3 w = words.Load3(12u * pixel);
    if ((pc.flags & kFixedPoint) != 0u) return float3(w) * pc.invScale;
    return asfloat(w);
}

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    uint2 p = id.xy;
    if (p.x >= pc.width || p.y >= pc.height) return;
    uint pixel = p.y * pc.width + p.x;
    float3 a = load(firstWords, pixel);
    if ((pc.flags & kCombinedOnly) != 0u) {
        outCombined[p] = float4(a, 1.0f);
        return;
    }
    float3 b = load(secondWords, pixel);
    outFirst[p] = float4(a, 1.0f);
    outSecond[p] = float4(b, 1.0f);
    outCombined[p] = float4(a + b, 1.0f);
}
