// Composite and tone map (mirror of shaders/vulkan/composite/composite.comp): final = direct +
// caustics, times exposure, ACES fit of Narkowicz 2015, sRGB-encoded (IEC 61966-2-1) into RGBA8;
// the selected AOV also goes linear to an RGBA32F target.
Texture2D<float4> direct : register(t0, space0);
Texture2D<float4> caustics : register(t1, space0);
Texture2D<float4> albedoMetallic : register(t2, space0);
Texture2D<float4> normalRoughness : register(t3, space0);
Texture2D<float4> linearDepth : register(t4, space0);
RWTexture2D<unorm float4> display : register(u5, space0);
RWTexture2D<float4> hdr : register(u6, space0);

static const uint kAovFinal = 0u, kAovDirect = 1u, kAovCaustics = 2u, kAovAlbedo = 3u, kAovNormal = 4u, kAovDepth = 5u;

struct Params { uint aov; uint hasCaustics; float exposure; float depthRange; uint2 size; };
ConstantBuffer<Params> params : register(b0, space999);

#include "common/tone_map.h"

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    int2 p = int2(id.xy);
    if (any(id.xy >= params.size)) return;
    float3 d = direct.Load(int3(p, 0)).rgb;
    float3 c = params.hasCaustics != 0u ? caustics.Load(int3(p, 0)).rgb : (float3)0.0f;
    float3 linearValue;
    float3 shown;
    if (params.aov == kAovAlbedo) {
        linearValue = albedoMetallic.Load(int3(p, 0)).rgb;
        shown = srgbEncode(linearValue);
    } else if (params.aov == kAovNormal) {
        linearValue = normalRoughness.Load(int3(p, 0)).xyz;
        shown = linearValue * 0.5f + 0.5f;
    } else if (params.aov == kAovDepth) {
        float z = linearDepth.Load(int3(p, 0)).x;
        linearValue = (float3)z;
        shown = (float3)(z > 0.0f ? 1.0f - saturate(z / params.depthRange) : 0.0f);
    } else {
        linearValue = params.aov == kAovDirect ? d : (params.aov == kAovCaustics ? c : d + c);
        shown = srgbEncode(acesFitted(linearValue * params.exposure));
    }
    display[p] = float4(shown, 1.0f);
    hdr[p] = float4(linearValue, 1.0f);
}
