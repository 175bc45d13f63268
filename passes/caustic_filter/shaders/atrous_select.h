#ifndef CAUSTICS_PASS_CAUSTIC_ATROUS_SELECT_H
#define CAUSTICS_PASS_CAUSTIC_ATROUS_SELECT_H
// caustics.atrous.N.select in the shared dialect (docs/shaders.md; docs/caustics.md "Quiet tiles"): one
// thread per pool tile, a pool tile that is listed (below the list's count, caustics.filterTiles.list)
// and was admitted to iteration N - 1 (every listed tile for N = 0) is admitted to iteration N when it or
// a tile within the iteration's reach (filterStepReachTiles) was noisy after the last pass that ran on it
// (quiet_tiles.h). Either way it is appended to iteration N's list (caustics.atrous.tiles, from listBase;
// its group count at word 4 N of caustics.atrous.tileArgs, set to (0, 1, 1, 0) by caustics.filterTiles),
// a tile not admitted with kFilterLeavesIterations set: iteration N's pairs pass writes its pool colour,
// the result of the passes that ran on it, into caustics.radiance, and its shares pass skips it.
// Entries: atrous_select.comp, atrous_select.hlsl.
#include "quiet_tiles.h"

CAUSTICS_SHARED_BEGIN
// Push constants (atrous_bindings.h), 20 bytes.
struct AtrousSelectParams {
    int stepWidth;   // iteration N's
    int width;
    int height;
    uint iteration;  // N
    uint listBase;   // iteration N's first word in caustics.atrous.tiles
};
CAUSTICS_SHARED_END

#if !defined(CAUSTICS_LANG_CPP)
#include "bindings/caustic_atrous_select.h"   // generated from passes/caustic_filter/atrous_bindings.h
#include "common/resources.h"

void atrousSelectThread(uint slot) {
    if (slot >= tileArgsLoad(0u)) return;   // not listed this frame
    if (params.iteration > 0u && progressLoad(filterIterationsWord(slot)) < params.iteration) return;   // left before
    int2 tile = filterTileOf(tilesLoad(slot));
    int reach = filterStepReachTiles(params.stepWidth);
    int2 tiles = int2((params.width + kFilterTileSize - 1) >> kFilterTileShift, (params.height + kFilterTileSize - 1) >> kFilterTileShift);
    bool admitted = false;
    for (int dy = -reach; dy <= reach && !admitted; ++dy) {
        for (int dx = -reach; dx <= reach && !admitted; ++dx) {
            int2 t = tile + int2(dx, dy);
            if (!filterInside(t, tiles.x, tiles.y)) continue;
            uint s = CAUSTICS_TEXEL_UINT(slotMap, t);
            admitted = s != kFilterNoSlot && progressLoad(filterNoisyWord(s)) != 0u;
        }
    }
    progressStore(filterIterationsWord(slot), admitted ? params.iteration + 1u : params.iteration);
    uint entry = params.listBase + iterationArgsAtomicAdd(4u * params.iteration, 1u);
    iterationTilesStore(entry, admitted ? slot : slot | kFilterLeavesIterations);
}
#endif

#endif  // CAUSTICS_PASS_CAUSTIC_ATROUS_SELECT_H
