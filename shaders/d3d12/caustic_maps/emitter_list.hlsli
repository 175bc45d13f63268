#ifndef CAUSTICS_D3D12_EMITTER_LIST_HLSLI
#define CAUSTICS_D3D12_EMITTER_LIST_HLSLI
// The emitter list's packing is the shared dialect's common/caustic_map.h, the statistics slots
// common/caustic_stats.h.
#include "common/caustic_map.h"
#include "common/caustic_stats.h"
#endif
