#ifndef CAUSTICS_D3D12_CAUSTIC_MAP_HLSLI
#define CAUSTICS_D3D12_CAUSTIC_MAP_HLSLI
// The map layer is the shared dialect's common/caustic_map.h; here its read from a byte-address
// buffer (the matrix column by column, common/matrix.h).
#include "common/caustic_map.h"

CausticMap loadCausticMap(ByteAddressBuffer b, uint index) {
    uint o = 176u * index;
    CausticMap m = b.Load<CausticMap>(o);
    m.viewProj = loadFloat4x4(b, o + 96u);
    return m;
}

// Does layer m own scene instance `instance`? (common/caustic_map.h, causticLayerOwnsEntry.)
bool causticLayerOwns(ByteAddressBuffer owners, CausticMap m, uint instanceCount, uint instance) {
    return causticLayerOwnsEntry(m, owners.Load(4u * (m.ownerRow * instanceCount + instance)));
}
#endif
