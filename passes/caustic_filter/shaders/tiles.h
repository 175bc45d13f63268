#ifndef CAUSTICS_PASS_CAUSTIC_FILTER_TILES_H
#define CAUSTICS_PASS_CAUSTIC_FILTER_TILES_H
// The filter's tile passes in the shared dialect (docs/shaders.md; docs/caustics.md "Filter", "Tiles"):
//  - caustics.filterTiles (tiles.comp / tiles.hlsl, one 8x8 group per 8x8 tile of the view): the tile
//    state counts the frames a tile's history is kept: keepFrames after a frame in which a photon reached
//    one of its pixels, else one less than the largest state among the history texels its pixels
//    reproject to (last frame's viewProj, as caustics.temporal does); bit 31 marks "photons this frame".
//  - caustics.filterTiles.list (tile_list.comp / tile_list.hlsl, one thread per tile): listed are the
//    tiles whose history is kept and the neighbours of tiles with photons, because the a-trous passes
//    spread a photon's radiance up to 14 pixels. A neighbour listed only so gets state 1: its history
//    (written this frame) is kept for the next frame's reprojection, then it drops out unless listed
//    again. Only bit 31 of a neighbour's state is read, and no write changes it, so the neighbours'
//    writes race harmlessly. A listed tile takes the next pool tile while the pool has room: tileArgs =
//    (tiles listed and given a pool tile, 1, 1, tiles that wanted one), set to (0, 1, 1, 0) by the first
//    group of caustics.filterTiles.
//    A tile past the capacity keeps no slot: the filter skips it (its pixels show this frame's
//    unfiltered radiance) and the host grows the pool for the next frames.
#include "filter_common.h"

CAUSTICS_SHARED_BEGIN
// Push constants (tiles_bindings.h), 8 and 12 bytes.
struct FilterTilesParams {
    uint historyValid;
    uint keepFrames;   // CausticsSettings::filterMaxHistory
};
struct TileListParams {
    int tilesX;
    int tilesY;
    uint capacity;     // pool tiles
};
// Tile state: frames the tile's history is kept (0: not listed, its texels stale), bit 31 set when a
// photon reached the tile this frame.
CAUSTICS_CONST uint kFilterTilePhotons = 0x80000000u;
CAUSTICS_CONST uint kFilterTileKeepMask = 0x7FFFFFFFu;

// A tile's state from its group's findings: photons this frame, or the largest carried state less one.
CAUSTICS_FN uint filterTileState(bool photons, uint carried, uint keepFrames) {
    return photons ? (keepFrames | kFilterTilePhotons) : max(carried, 1u) - 1u;
}
CAUSTICS_SHARED_END

#endif  // CAUSTICS_PASS_CAUSTIC_FILTER_TILES_H
