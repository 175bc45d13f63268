#ifndef CAUSTICS_PASS_CAUSTICS_OUTPUT_H
#define CAUSTICS_PASS_CAUSTICS_OUTPUT_H
// Caustic radiance into the host's target, the body of the caustics-only output pass in the shared
// dialect (docs/shaders.md; docs/embedding.md "Output target"): one triangle covers the viewport and
// each fragment returns the caustic radiance of its pixel times the host's scale. The pipeline's blend
// state makes the store Replace (no blending) or Add (ONE + ONE: dst += src). The target is a colour
// attachment, not a storage image: that takes every float and unorm colour format on Vulkan and D3D12
// (BGRA8 and sRGB included, which storage images do not), converts on store (sRGB encoded by the
// hardware, blending done in linear) and needs no format-less storage reads for Add.
// Entries: caustics_output.vert, caustics_output.frag, caustics_output.hlsl (CAUSTICS_STAGE_*).
#include "common/resources.h"

CAUSTICS_SHARED_BEGIN

// Push constants (caustics_output_bindings.h), 8 bytes.
struct CausticsOutputParams {
    float scale;   // FrameInputs::outputScale: the host's exposure (pre-exposure) of its lit buffer
    float alpha;   // Replace: 1 (opaque); Add: 0, so ONE + ONE keeps the host's alpha
};

// Vertex 0, 1, 2 of the triangle (-1,-1), (3,-1), (-1,3) in clip space: it covers the whole viewport.
CAUSTICS_FN float4 fullScreenTriangleVertex(uint vertexIndex) {
    float2 p = float2(float((vertexIndex << 1u) & 2u), float(vertexIndex & 2u));
    return float4(p * 2.0f - 1.0f, 0.0f, 1.0f);
}

CAUSTICS_FN float4 causticsOutputValue(CausticsOutputParams params, float3 radiance) {
    return float4(radiance * params.scale, params.alpha);
}

CAUSTICS_SHARED_END

#if defined(CAUSTICS_STAGE_FRAG) && !defined(CAUSTICS_LANG_CPP)
#include "bindings/caustics_output.h"   // generated from passes/caustics_output/caustics_output_bindings.h

// The fragment at window position `fragCoord` (pixel centres at .5): the caustics at that pixel.
float4 causticsOutputFragment(float4 fragCoord) {
    return causticsOutputValue(params, CAUSTICS_TEXEL(caustics, int2(fragCoord.xy)).rgb);
}
#endif

#endif  // CAUSTICS_PASS_CAUSTICS_OUTPUT_H
