#ifndef CAUSTICS_PASS_CAUSTIC_FILTER_OUTPUT_H
#define CAUSTICS_PASS_CAUSTIC_FILTER_OUTPUT_H
// caustics.filterOutput in the shared dialect (docs/shaders.md): with no a-trous iteration the temporal
// result is the module's radiance, written over the listed tiles only into caustics.radiance (whose
// unlisted tiles hold this frame's zeros; docs/caustics.md "Tiles"). A pixel without history (n = 1)
// keeps this frame's radiance as it is: the temporal result is that frame, and the pool's pre-exposed
// half precision would only round it. Entries: output.comp, output.hlsl.
#include "filter_common.h"

CAUSTICS_SHARED_BEGIN
// Push constants (output_bindings.h), 12 bytes.
struct FilterOutputParams {
    int width;
    int height;
    float invPreExposure;   // pool units -> radiance
};
CAUSTICS_SHARED_END

#if !defined(CAUSTICS_LANG_CPP)
#include "bindings/caustic_filter_output.h"   // generated from passes/caustic_filter/output_bindings.h
#include "common/resources.h"

void filterOutputThread(uint group, uint2 local) {
    int2 p = filterTileOf(tilesLoad(group)) * kFilterTileSize + int2(local);
    if (!filterInside(p, params.width, params.height)) return;
    int2 own = filterPoolTexel(group, p);
    if (filterGuideLength(CAUSTICS_TEXEL(temporalGuides, own).x) <= 1.0f) return;
    int2 target = SPECULAR_INPUT_TEXEL(p, FILTER_LIST_ORDER_ON);
    if (target.x < 0) return;
    CAUSTICS_IMAGE_STORE(radiance, target, float4(CAUSTICS_TEXEL(temporalColor, own).rgb * params.invPreExposure, 1.0f));
}
#endif

#endif  // CAUSTICS_PASS_CAUSTIC_FILTER_OUTPUT_H
