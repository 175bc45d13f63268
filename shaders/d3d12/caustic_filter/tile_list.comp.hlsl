// The filter's tile list (mirror of shaders/vulkan/caustic_filter/tile_list.comp): tiles with a state and
// the neighbours of tiles with photons (those get state 1); bit 31 of a state is never changed here.
// Each listed tile takes the next pool tile while the pool has room; tileArgs = (tiles given a pool
// tile, 1, 1, tiles that wanted one).
#include "caustic_filter/filter_common.hlsli"
globallycoherent RWTexture2D<uint> tileState : register(u0, space0);
RWByteAddressBuffer tileArgs : register(u1, space0);
RWByteAddressBuffer tiles : register(u2, space0);
RWTexture2D<uint> slotMap : register(u3, space0);
struct Push { int tilesX; int tilesY; uint capacity; };
ConstantBuffer<Push> pc : register(b0, space999);

[numthreads(8, 8, 1)]
void main(uint3 tid : SV_DispatchThreadID) {
    int2 t = int2(tid.xy);
    if (t.x >= pc.tilesX || t.y >= pc.tilesY) return;
    uint state = tileState[t];
    bool listed = state != 0u;
    for (int dy = -1; dy <= 1 && !listed; ++dy)
        for (int dx = -1; dx <= 1 && !listed; ++dx) {
            int2 n = t + int2(dx, dy);
            if (all(n >= int2(0, 0)) && n.x < pc.tilesX && n.y < pc.tilesY)
                listed = (tileState[n] & kFilterTilePhotons) != 0u;
        }
    uint slot = kFilterNoSlot;
    if (listed) {
        uint wanted;
        tileArgs.InterlockedAdd(12, 1u, wanted);
        if (wanted < pc.capacity) {
            slot = wanted;
            uint ignored;
            tileArgs.InterlockedAdd(0, 1u, ignored);
            tiles.Store(4u * slot, uint(t.x) | (uint(t.y) << 16));
            if (state == 0u) tileState[t] = 1u;
        }
    }
    slotMap[t] = slot;
}
