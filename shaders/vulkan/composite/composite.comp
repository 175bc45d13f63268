#version 460
#extension GL_EXT_samplerless_texture_functions : require
#extension GL_GOOGLE_include_directive : require
// Composite and tone map (DESIGN.md pass 7): final = direct + caustic radiance (linear), times the
// exposure, tone-mapped with the ACES filmic fit of Narkowicz 2015 ("ACES Filmic Tone Mapping Curve":
// x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14)), then sRGB-encoded (IEC 61966-2-1) into RGBA8.
// The selected AOV also goes, linear and un-tone-mapped, to an RGBA32F target (EXR output).
#include "common/tone_map.h"
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D direct;
layout(set = 0, binding = 1) uniform texture2D caustics;
layout(set = 0, binding = 2) uniform texture2D albedoMetallic;
layout(set = 0, binding = 3) uniform texture2D normalRoughness;
layout(set = 0, binding = 4) uniform texture2D linearDepth;
layout(set = 0, binding = 5, rgba8) uniform writeonly image2D display;
layout(set = 0, binding = 6, rgba32f) uniform writeonly image2D hdr;

// Must match caustics::CompositeAov (passes/composite/composite_pass.h).
const uint kAovFinal = 0u, kAovDirect = 1u, kAovCaustics = 2u, kAovAlbedo = 3u, kAovNormal = 4u, kAovDepth = 5u;

layout(push_constant) uniform Params {
    uint aov;
    uint hasCaustics;   // 0: caustic radiance is zero (the binding repeats `direct` and is not read)
    float exposure;
    float depthRange;   // Depth AOV: metres mapped to white
    uvec2 size;
} params;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(p), params.size))) return;
    vec3 d = texelFetch(direct, p, 0).rgb;
    vec3 c = params.hasCaustics != 0u ? texelFetch(caustics, p, 0).rgb : vec3(0.0);

    vec3 linear;
    vec3 shown;
    if (params.aov == kAovAlbedo) {
        linear = texelFetch(albedoMetallic, p, 0).rgb;
        shown = srgbEncode(linear);
    } else if (params.aov == kAovNormal) {
        linear = texelFetch(normalRoughness, p, 0).xyz;
        shown = linear * 0.5 + 0.5;   // a visualisation, not a colour: no sRGB curve
    } else if (params.aov == kAovDepth) {
        float z = texelFetch(linearDepth, p, 0).x;
        linear = vec3(z);
        shown = vec3(z > 0.0 ? 1.0 - clamp(z / params.depthRange, 0.0, 1.0) : 0.0);
    } else {
        linear = params.aov == kAovDirect ? d : (params.aov == kAovCaustics ? c : d + c);
        shown = srgbEncode(acesFitted(linear * params.exposure));
    }
    imageStore(display, p, vec4(shown, 1.0));
    imageStore(hdr, p, vec4(linear, 1.0));
}
