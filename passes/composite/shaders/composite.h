#ifndef CAUSTICS_PASS_COMPOSITE_H
#define CAUSTICS_PASS_COMPOSITE_H
// Composite and tone map, the body of the composite pass in the shared dialect (docs/shaders.md):
// final = direct + caustic radiance (linear), times the exposure, tone-mapped with the ACES fit of
// Narkowicz 2015 and sRGB-encoded (common/tone_map.h) into RGBA8. The selected AOV also goes, linear
// and un-tone-mapped, to an RGBA32F target (EXR output). Entries: composite.comp, composite.hlsl.
#include "common/resources.h"
#include "common/tone_map.h"

CAUSTICS_SHARED_BEGIN

// caustics::CompositeAov (passes/composite/composite_pass.h; static_assert in composite_pass.cpp).
CAUSTICS_CONST uint kAovFinal = 0u;
CAUSTICS_CONST uint kAovDirect = 1u;
CAUSTICS_CONST uint kAovCaustics = 2u;
CAUSTICS_CONST uint kAovAlbedo = 3u;
CAUSTICS_CONST uint kAovNormal = 4u;
CAUSTICS_CONST uint kAovDepth = 5u;

// Push constants (composite_bindings.h), 24 bytes.
struct CompositeParams {
    uint aov;
    uint hasCaustics;   // 0: caustic radiance is zero (the binding repeats `direct` and is not used)
    float exposure;
    float depthRange;   // Depth AOV: metres mapped to white
    uint2 size;
};

// One pixel's G-buffer and radiance inputs.
struct CompositeInputs {
    float3 direct;
    float3 caustics;
    float3 albedo;
    float3 normal;
    float linearDepth;
};

struct CompositeOutput {
    float3 shown;         // display value, before the RGBA8 store
    float3 linearValue;   // the selected AOV, linear
};

CAUSTICS_FN CompositeOutput compositePixel(CompositeParams params, CompositeInputs t) {
    float3 d = t.direct;
    float3 c = params.hasCaustics != 0u ? t.caustics : splat3(0.0f);
    CompositeOutput o;
    if (params.aov == kAovAlbedo) {
        o.linearValue = t.albedo;
        o.shown = srgbEncode(o.linearValue);
    } else if (params.aov == kAovNormal) {
        o.linearValue = t.normal;
        o.shown = o.linearValue * 0.5f + 0.5f;   // a visualisation, not a colour: no sRGB curve
    } else if (params.aov == kAovDepth) {
        float z = t.linearDepth;
        o.linearValue = splat3(z);
        o.shown = splat3(z > 0.0f ? 1.0f - saturate(z / params.depthRange) : 0.0f);
    } else {
        o.linearValue = params.aov == kAovDirect ? d : (params.aov == kAovCaustics ? c : d + c);
        o.shown = srgbEncode(acesFitted(o.linearValue * params.exposure));
    }
    return o;
}

CAUSTICS_SHARED_END

#if !defined(CAUSTICS_LANG_CPP)
#include "bindings/composite.h"   // generated from passes/composite/composite_bindings.h

// The thread of an 8 x 8 group at pixel `id`: reads the generated bindings (bindings/composite.*).
void compositeThread(uint2 id) {
    if (id.x >= params.size.x || id.y >= params.size.y) return;
    int2 p = int2(id);
    CompositeInputs t;
    t.direct = CAUSTICS_TEXEL(direct, p).rgb;
    t.caustics = CAUSTICS_TEXEL(caustics, p).rgb;
    t.albedo = CAUSTICS_TEXEL(albedoMetallic, p).rgb;
    t.normal = CAUSTICS_TEXEL(normalRoughness, p).xyz;
    t.linearDepth = CAUSTICS_TEXEL(linearDepth, p).x;
    CompositeOutput o = compositePixel(params, t);
    CAUSTICS_IMAGE_STORE(display, p, float4(o.shown, 1.0f));
    CAUSTICS_IMAGE_STORE(hdr, p, float4(o.linearValue, 1.0f));
}
#endif

#endif  // CAUSTICS_PASS_COMPOSITE_H
