#ifndef CAUSTICS_PASS_CAUSTIC_FILTER_TILES_THREAD_H
#define CAUSTICS_PASS_CAUSTIC_FILTER_TILES_THREAD_H
// caustics.filterTiles' thread function (GLSL and HLSL; tiles.h says what it computes).
#include "tiles.h"
// The entry includes the camera's struct first (scene/camera.glsl or .hlsli; temporal_thread.h says why).
#include "bindings/caustic_filter_tiles.h"   // generated from passes/caustic_filter/tiles_bindings.h
#include "common/resources.h"

CAUSTICS_GROUPSHARED uint sPhotons;
CAUSTICS_GROUPSHARED uint sCarried;

// Largest previous tile state among the history texels caustics.temporal may read for a pixel that
// reprojects to `prev`: the 2x2 bilinear taps and the 3x3 around the nearest texel.
uint filterCarriedState(float2 prev, int2 size) {
    int2 lo = max(int2(floor(prev)) - int2(1, 1), int2(0, 0)), hi = min(int2(floor(prev)) + int2(2, 2), size - int2(1, 1));
    if (lo.x > hi.x || lo.y > hi.y) return 0u;
    uint m = 0u;
    for (int ty = lo.y / kFilterTileSize; ty <= hi.y / kFilterTileSize; ++ty)
        for (int tx = lo.x / kFilterTileSize; tx <= hi.x / kFilterTileSize; ++tx)
            m = max(m, CAUSTICS_TEXEL_UINT(previousTiles, int2(tx, ty)) & kFilterTileKeepMask);
    return m;
}

// The list pass's indirect arguments start at (0 listed, 1, 1, 0 wanted): set here, not by a transfer
// pass of their own (docs/caustics.md "Tiles").
void filterTilesInitArgs(uint2 group, uint local) {
    if (group.x == 0u && group.y == 0u && local < 4u) tileArgsStore(local, local == 1u || local == 2u ? 1u : 0u);
}

void filterTilesThread(uint2 group, uint2 pixel, uint local) {
    // List order (common/specular_list.h): a tile with no listed pixel has neither this frame's second type
    // nor a guide to carry a history with, so its state is 0 without reading its pixels (the group's
    // threads take the same branch: the barriers below stay uniform).
    if (FILTER_LIST_ORDER_ON != 0u) {
        uint4 run = CAUSTICS_TEXEL(specularIndex, int2(group));
        if ((run.y | run.z) == 0u) {
            if (local == 0u) CAUSTICS_IMAGE_STORE_UINT(tileState, int2(group), 0u);
            filterTilesInitArgs(group, local);
            return;
        }
    }
    if (local == 0u) {
        sPhotons = 0u;
        sCarried = 0u;
    }
    CAUSTICS_GROUP_BARRIER();
    int2 p = int2(pixel);
    int2 size = int2(camera.frame.xy);
    if (p.x < size.x && p.y < size.y) {
        int2 t = SPECULAR_INPUT_TEXEL(p, FILTER_LIST_ORDER_ON);
        float3 c = FILTER_INPUT(current, t).rgb;
        if (max(c.r, max(c.g, c.b)) > 0.0f) CAUSTICS_GROUP_ATOMIC_OR(sPhotons, 1u);
        float depth = FILTER_INPUT(gLinearDepth, t).r;
        if (params.historyValid != 0u && FILTER_INPUT_UINT(gObjectId, t) != 0u && depth > 0.0f) {
            float4 clip = mul(camera.prevViewProj, float4(cameraWorldPosition(camera, float2(p) + 0.5f, depth), 1.0f));
            if (clip.w > 0.0f)
                CAUSTICS_GROUP_ATOMIC_MAX(sCarried, filterCarriedState((clip.xy / clip.w * 0.5f + 0.5f) * float2(size) - 0.5f, size));
        }
    }
    CAUSTICS_GROUP_BARRIER();
    if (local == 0u) CAUSTICS_IMAGE_STORE_UINT(tileState, int2(group), filterTileState(sPhotons != 0u, sCarried, params.keepFrames));
    filterTilesInitArgs(group, local);
}

#endif  // CAUSTICS_PASS_CAUSTIC_FILTER_TILES_THREAD_H
