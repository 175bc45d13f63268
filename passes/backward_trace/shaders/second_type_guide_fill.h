#ifndef CAUSTICS_PASS_SECOND_TYPE_GUIDE_FILL_H
#define CAUSTICS_PASS_SECOND_TYPE_GUIDE_FILL_H
// Fills the second type's guides where this frame's backward sample made no sphere (it was reflected
// away, with probability R, or left the scene) or made one along a less probable lobe (its guides are
// not written: second_type_guides.h), in the shared dialect (docs/shaders.md; docs/caustics.md
// "Second-type guides"). Such a pixel's second type is a legitimate zero of the estimate, but with
// guide id 0 the filter could not average it with its neighbours and it would stay a hole. It takes the
// guides of the first of its 8 neighbours (fixed order: deterministic) that has a sphere and shows the
// same object in the camera G-buffer (the same glass). Entries: second_type_guide_fill.comp, .hlsl.
// In place: a thread writes only its own pixel, and only where the sphere pass wrote no guide; it reads
// the guides only of pixels the sphere pass wrote (sphereObjectId, which no thread here writes, says
// which), so no thread reads a texel another one writes. The sphere-written textures are not copied:
// at 1080p that copy was the second type's largest transient (docs/caustics.md "Second-type guides").
#include "common/resources.h"
#include "common/specular_list.h"

CAUSTICS_SHARED_BEGIN
// Push constants (second_type_guide_fill_bindings.h), 16 bytes.
struct SecondTypeGuideFillParams {
    uint2 size;       // the image, pixels
    uint listOrder;   // 1: the guides hold one texel per list entry (common/specular_list.h)
    uint pad;
};

// The k-th neighbour (k < 8): the four edge neighbours first, then the diagonals.
CAUSTICS_FN int2 guideFillNeighbour(uint k) {
    int sign = (k & 1u) == 0u ? 1 : -1;
    if (k < 2u) return int2(sign, 0);
    if (k < 4u) return int2(0, sign);
    return int2(sign, k < 6u ? 1 : -1);
}
CAUSTICS_SHARED_END

#if !defined(CAUSTICS_LANG_CPP)
#include "bindings/second_type_guide_fill.h"   // generated from passes/backward_trace/second_type_guide_fill_bindings.h

// One thread per pixel, or, in list order, per listed entry (its texel; the pixel from the list): only
// listed pixels have guides there.
void secondTypeGuideFillThread(uint2 id) {
    int2 p = int2(id), t = int2(id);
    if (params.listOrder != 0u) {
        uint entry = (id.y << kSpecularListRowShift) + id.x;
        if (entry >= listCountLoad(0u)) return;
        uint pixel = specularPixelsLoad(entry);
        p = int2(int(pixel % params.size.x), int(pixel / params.size.x));
    } else if (id.x >= params.size.x || id.y >= params.size.y) {
        return;
    }
    uint own = CAUSTICS_TEXEL_UINT(sphereObjectId, t);
    if (own != 0u) {   // the sphere pass wrote the pixel's depth, motion and normal
        CAUSTICS_IMAGE_STORE_UINT(objectId, t, own);
        return;
    }
    uint surface = CAUSTICS_TEXEL_UINT(cameraObjectId, p);
    float4 depthMotionHere = float4(0.0f, 0.0f, 0.0f, 0.0f), normalHere = float4(0.0f, 0.0f, 0.0f, 0.0f);
    uint idHere = 0u;
    for (uint k = 0u; k < 8u && surface != 0u; ++k) {
        int2 q = p + guideFillNeighbour(k);
        if (q.x < 0 || q.y < 0 || q.x >= int(params.size.x) || q.y >= int(params.size.y)) continue;
        int2 tq = SPECULAR_INPUT_TEXEL(q, params.listOrder);
        if (tq.x < 0) continue;
        uint source = CAUSTICS_TEXEL_UINT(sphereObjectId, tq);
        if (source == 0u || CAUSTICS_TEXEL_UINT(cameraObjectId, q) != surface) continue;
        depthMotionHere = CAUSTICS_IMAGE_LOAD(depthMotion, tq);
        // A filled pixel's photon weight (.w) is stored negated: its sample is not the neighbour's, so the
        // filter's shot-noise estimate takes the weight but not the pixel's luminance (variance.h).
        normalHere = CAUSTICS_IMAGE_LOAD(normal, tq);
        normalHere.w = -abs(normalHere.w);
        idHere = source;
        break;
    }
    CAUSTICS_IMAGE_STORE(depthMotion, t, depthMotionHere);
    CAUSTICS_IMAGE_STORE(normal, t, normalHere);
    CAUSTICS_IMAGE_STORE_UINT(objectId, t, idHere);
}
#endif

#endif  // CAUSTICS_PASS_SECOND_TYPE_GUIDE_FILL_H
