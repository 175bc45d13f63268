#version 460
#extension GL_GOOGLE_include_directive : require
// The filter's tile list (docs/caustics.md "Filter", "Tiles"), one thread per tile: listed are the tiles
// whose history is kept (state, tiles.comp) and the neighbours of tiles with photons, because the a-trous
// passes spread a photon's radiance up to 14 pixels. A neighbour listed only so gets state 1: its history
// (written this frame) is kept for the next frame's reprojection, then it drops out unless listed again.
// Only bit 31 of a neighbour's state is read here, and no write changes it, so the neighbours' writes
// race harmlessly. A listed tile takes the next pool tile (filter_common.glsl, "pool") while the pool
// has room: tileArgs = (tiles listed and given a pool tile, 1, 1, tiles that wanted one); it is cleared
// to (0, 1, 1, 0) before this pass. A tile past the capacity keeps no slot: the filter skips it (its
// pixels show this frame's unfiltered radiance) and the host grows the pool for the next frames.
layout(local_size_x = 8, local_size_y = 8) in;
#include "caustic_filter/filter_common.glsl"
layout(set = 0, binding = 0, r32ui) uniform coherent uimage2D tileState;
layout(set = 0, binding = 1, std430) buffer TileArgs { uint tileArgs[]; };
layout(set = 0, binding = 2, std430) writeonly buffer TileList { uint tiles[]; };
layout(set = 0, binding = 3, r32ui) uniform writeonly uimage2D slotMap;   // this frame's pool tile per tile
layout(push_constant) uniform Push { int tilesX; int tilesY; uint capacity; } pc;

void main() {
    ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    if (t.x >= pc.tilesX || t.y >= pc.tilesY) return;
    uint state = imageLoad(tileState, t).r;
    bool listed = state != 0u;
    for (int dy = -1; dy <= 1 && !listed; ++dy)
        for (int dx = -1; dx <= 1 && !listed; ++dx) {
            ivec2 n = t + ivec2(dx, dy);
            if (all(greaterThanEqual(n, ivec2(0))) && n.x < pc.tilesX && n.y < pc.tilesY)
                listed = (imageLoad(tileState, n).r & kFilterTilePhotons) != 0u;
        }
    uint slot = kFilterNoSlot;
    if (listed) {
        uint wanted = atomicAdd(tileArgs[3], 1u);
        if (wanted < pc.capacity) {
            slot = wanted;
            atomicAdd(tileArgs[0], 1u);
            tiles[slot] = uint(t.x) | (uint(t.y) << 16);
            if (state == 0u) imageStore(tileState, t, uvec4(1u));
        }
    }
    imageStore(slotMap, t, uvec4(slot));
}
