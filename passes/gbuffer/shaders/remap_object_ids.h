#ifndef CAUSTICS_PASS_REMAP_OBJECT_IDS_H
#define CAUSTICS_PASS_REMAP_OBJECT_IDS_H
// A host G-buffer's own object ids -> the module's (docs/embedding.md, "Instance ids"), the body of
// the object-id remap pass in the shared dialect (docs/shaders.md): every pixel's host id is looked up
// in the host's map, (hostId, moduleId) pairs sorted by hostId, by binary search; an id the map does
// not list becomes 0 (background: no caustic lands there, no backward ray starts).
// Entries: remap_object_ids.comp, remap_object_ids.hlsl.
#include "common/resources.h"

CAUSTICS_SHARED_BEGIN
// Push constants (remap_object_ids_bindings.h), 16 bytes.
struct ObjectIdRemapParams {
    uint2 size;
    uint pairCount;
    uint pad;
};
CAUSTICS_SHARED_END

#if defined(CAUSTICS_LANG_CPP)
namespace caustics::shader {
uint2 pairsLoad(uint i);   // the map's i-th pair: defined by the C++ caller (tests)
}
#else
#include "bindings/remap_object_ids.h"   // generated from passes/gbuffer/remap_object_ids_bindings.h
#endif

CAUSTICS_SHARED_BEGIN
// The module id of `hostId` in the first `pairCount` pairs of the map, 0 if it is not listed.
CAUSTICS_FN uint moduleObjectIdOf(uint hostId, uint pairCount) {
    uint lo = 0u, hi = pairCount;   // first pair with pair.x >= hostId
    while (lo < hi) {
        uint mid = (lo + hi) / 2u;
        if (pairsLoad(mid).x < hostId) lo = mid + 1u; else hi = mid;
    }
    return (lo < pairCount && pairsLoad(lo).x == hostId) ? pairsLoad(lo).y : 0u;
}
CAUSTICS_SHARED_END

#if !defined(CAUSTICS_LANG_CPP)
// The thread of an 8 x 8 group at pixel `id`.
void remapObjectIdsThread(uint2 id) {
    if (id.x >= params.size.x || id.y >= params.size.y) return;
    int2 p = int2(id);
    uint hostId = CAUSTICS_TEXEL_UINT(hostObjectId, p);
    CAUSTICS_IMAGE_STORE_UINT(moduleObjectId, p, moduleObjectIdOf(hostId, params.pairCount));
}
#endif

#endif  // CAUSTICS_PASS_REMAP_OBJECT_IDS_H
