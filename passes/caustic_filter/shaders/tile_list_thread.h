#ifndef CAUSTICS_PASS_CAUSTIC_TILE_LIST_THREAD_H
#define CAUSTICS_PASS_CAUSTIC_TILE_LIST_THREAD_H
// caustics.filterTiles.list's thread function (GLSL and HLSL; tiles.h says what it computes).
#include "tiles.h"
#include "bindings/caustic_tile_list.h"   // generated from passes/caustic_filter/tiles_bindings.h
#include "common/resources.h"

void tileListThread(uint2 id) {
    int2 t = int2(id);
    if (t.x >= params.tilesX || t.y >= params.tilesY) return;
    uint state = CAUSTICS_IMAGE_LOAD_UINT(tileState, t);
    bool listed = state != 0u;
    for (int dy = -1; dy <= 1 && !listed; ++dy)
        for (int dx = -1; dx <= 1 && !listed; ++dx) {
            int2 n = t + int2(dx, dy);
            if (n.x >= 0 && n.y >= 0 && n.x < params.tilesX && n.y < params.tilesY)
                listed = (CAUSTICS_IMAGE_LOAD_UINT(tileState, n) & kFilterTilePhotons) != 0u;
        }
    uint slot = kFilterNoSlot;
    if (listed) {
        uint wanted = tileArgsAtomicAdd(3u, 1u);
        if (wanted < params.capacity) {
            slot = wanted;
            tileArgsAtomicAdd(0u, 1u);
            tilesStore(slot, uint(t.x) | (uint(t.y) << 16));
            if (state == 0u) CAUSTICS_IMAGE_STORE_UINT(tileState, t, 1u);
        }
    }
    CAUSTICS_IMAGE_STORE_UINT(slotMap, t, slot);
}

#endif  // CAUSTICS_PASS_CAUSTIC_TILE_LIST_THREAD_H
