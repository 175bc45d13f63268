#ifndef CAUSTICS_PASS_GRID_FROM_COUNT_H
#define CAUSTICS_PASS_GRID_FROM_COUNT_H
// The grid of an indirect ray dispatch from a GPU counter, in the shared dialect (docs/shaders.md):
// (min(counter, cap), 1, 1), or 0 launches when the gate counter is 0. caustics.gather is dispatched
// from the stored-hit count this way, gated by the sphere count, so its cost follows the stored hits
// and the spheres instead of CausticsSettings::maxStoredHits (docs/caustics.md, "Cost that follows the
// caustic work"). Entries: grid_from_count.comp, grid_from_count.hlsl.
#include "common/lang.h"

CAUSTICS_SHARED_BEGIN
// Push constants (grid_from_count_bindings.h), 12 bytes: slots of caustics.stats and the cap.
struct GridFromCountParams {
    uint slot;       // the counter that sets the launches
    uint cap;        // at most this many
    uint gateSlot;   // 0 there: no launch
};
CAUSTICS_SHARED_END

#if defined(CAUSTICS_LANG_CPP)
namespace caustics::shader {
uint countersLoad(uint i);         // caustics.stats: defined by the C++ caller (tests)
void gridStore(uint i, uint v);    // the 12-byte grid
}
#else
#include "bindings/grid_from_count.h"   // generated from passes/caustic_maps/grid_from_count_bindings.h
#endif

CAUSTICS_SHARED_BEGIN
CAUSTICS_FN void writeGridFromCount(GridFromCountParams p) {
    gridStore(0u, countersLoad(p.gateSlot) == 0u ? 0u : min(countersLoad(p.slot), p.cap));
    gridStore(1u, 1u);
    gridStore(2u, 1u);
}
CAUSTICS_SHARED_END

#endif  // CAUSTICS_PASS_GRID_FROM_COUNT_H
