#ifndef CAUSTICS_D3D12_SPHERE_LIST_HLSLI
#define CAUSTICS_D3D12_SPHERE_LIST_HLSLI
// Statistics slots of the second type's cost: now named once, with every slot, in common/caustic_stats.h.
#include "common/caustic_stats.h"
#endif
