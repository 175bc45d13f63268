#ifndef CAUSTICS_PASS_COMBINE_TYPES_H
#define CAUSTICS_PASS_COMBINE_TYPES_H
// caustics.radiance = the first type filtered on the camera G-buffer (its own texture, or already in
// caustics.radiance) + the second type filtered on its own guides (docs/caustics.md "Second-type
// guides"), in the shared dialect (docs/shaders.md), one thread per pixel; the second type at the pixel
// or, in list order, at its list entry (common/specular_list.h).
// Entries: combine_types.comp, combine_types.hlsl.
#include "common/resources.h"
#include "filter_common.h"

CAUSTICS_SHARED_BEGIN
// Push constants (combine_types_bindings.h), 16 bytes.
struct CombineTypesParams {
    uint2 size;
    uint addToRadiance;   // 1: radiance holds the filtered first type (firstType unread): add the second
    uint pad;             // std430 rounds the block up to its uint2's 8-byte alignment
};
CAUSTICS_SHARED_END

#if !defined(CAUSTICS_LANG_CPP)
#include "bindings/combine_types.h"   // generated from passes/caustic_filter/combine_types_bindings.h

void combineTypesThread(uint2 id) {
    if (id.x >= params.size.x || id.y >= params.size.y) return;
    int2 p = int2(id);
    int2 second = SPECULAR_INPUT_TEXEL(p, FILTER_LIST_ORDER_ON);
    // In list order a pixel with no entry has no second type: radiance (the first type) is left as it is.
    if (second.x < 0) return;
    float3 first = params.addToRadiance != 0u ? CAUSTICS_IMAGE_LOAD(radiance, p).rgb : CAUSTICS_TEXEL(firstType, p).rgb;
    CAUSTICS_IMAGE_STORE(radiance, p, float4(first + CAUSTICS_TEXEL(secondType, second).rgb, 1.0f));
}
#endif

#endif  // CAUSTICS_PASS_COMBINE_TYPES_H
