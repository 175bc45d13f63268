#ifndef CAUSTICS_PASS_CAUSTIC_QUIET_TILES_H
#define CAUSTICS_PASS_CAUSTIC_QUIET_TILES_H
// Quiet tiles leave the a-trous iterations (docs/caustics.md "Quiet tiles"): after caustics.variance and
// after each a-trous iteration but the last, a tile is noisy when one of its pixels' estimated deviation
// of the mean (the pool's alpha, pre-exposed) exceeds max(relative x its luminance, floor), and young
// while one of its pixels' history is shorter than the cap (filterMaxHistory: its variance estimate is
// young too, and so the tile stays in every iteration); the next iteration's caustics.atrous.N.select
// admits a tile when it or a tile the iteration's kernel reaches from it is noisy or young; the
// iteration's pairs pass writes the result of a tile it does not admit into caustics.radiance. A
// converged history needs no more spatial filtering than its noise asks for, and the filter's cost
// then follows the noise the camera sees (NRD's REBLUR likewise shrinks its blur as the history grows).
// caustics.filterProgress holds two words per pool tile: the noisy and young flags of the last pass that
// ran on the tile, and the number of iterations it was admitted to; a tile admitted to fewer than N + 1
// is neither a source nor a receiver of iteration N (atrous_thread.h), so the energy stays where it was.
#include "filter_common.h"

CAUSTICS_SHARED_BEGIN
// An iteration's list entry of a tile that leaves the iterations there (atrous_select.h): its pool tile
// with this bit set.
CAUSTICS_CONST uint kFilterLeavesIterations = 0x80000000u;
// The flags word's bits.
CAUSTICS_CONST uint kFilterTileNoisy = 1u;
CAUSTICS_CONST uint kFilterTileYoung = 2u;
CAUSTICS_FN uint filterNoisyWord(uint slot) { return 2u * slot; }
CAUSTICS_FN uint filterIterationsWord(uint slot) { return 2u * slot + 1u; }

// Whether another iteration can still lower a pixel's noise visibly (CausticsSettings::filterQuiet*).
CAUSTICS_FN bool filterPixelNoisy(float luminance, float deviation, float relative, float floorDeviation) {
    return deviation > max(relative * luminance, floorDeviation);
}

// The tiles around a tile that an iteration of step s reaches: its 5x5 kernel spans 2 s pixels.
CAUSTICS_FN int filterStepReachTiles(int step) { return (2 * step + kFilterTileSize - 1) >> kFilterTileShift; }
CAUSTICS_SHARED_END

#if !defined(CAUSTICS_LANG_CPP)
// The group's flags: cleared by thread 0 before a barrier the pass already has (filterQuietClear), set
// by any pixel, stored by thread 0 after one more barrier (filterQuietStore, in a pass that defines
// FILTER_QUIET_STORE and binds caustics.filterProgress writable as `progress`).
FILTER_GROUPSHARED uint sFilterFlags;

void filterQuietClear(uint local) {
    if (local == 0u) sFilterFlags = 0u;
}

#if defined(FILTER_QUIET_STORE)
// Every thread of the group calls it (a barrier). keepYoung: the tile's young flag stays as the pass
// before stored it (the a-trous passes; caustics.variance sets it).
void filterQuietStore(uint slot, uint local, uint flags, bool keepYoung) {
    if (flags != 0u) FILTER_ATOMIC_OR(sFilterFlags, flags);
    FILTER_BARRIER();
    if (local != 0u) return;
    uint young = keepYoung ? progressLoad(filterNoisyWord(slot)) & kFilterTileYoung : 0u;
    progressStore(filterNoisyWord(slot), sFilterFlags | young);
}
#endif
#endif

#endif  // CAUSTICS_PASS_CAUSTIC_QUIET_TILES_H
