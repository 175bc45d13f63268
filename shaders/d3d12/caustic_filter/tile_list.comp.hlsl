// The filter's tile list (mirror of shaders/vulkan/caustic_filter/tile_list.comp): tiles with a state and
// the neighbours of tiles with photons (those get state 1); bit 31 of a state is never changed here.
#include "caustic_filter/filter_common.hlsli"
globallycoherent RWTexture2D<uint> tileState : register(u0, space0);
RWByteAddressBuffer tileArgs : register(u1, space0);   // (listed tiles, 1, 1)
RWByteAddressBuffer tiles : register(u2, space0);
struct Push { int tilesX; int tilesY; };
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
    if (!listed) return;
    if (state == 0u) tileState[t] = 1u;
    uint slot;
    tileArgs.InterlockedAdd(0, 1u, slot);
    tiles.Store(4u * slot, uint(t.x) | (uint(t.y) << 16));
}
