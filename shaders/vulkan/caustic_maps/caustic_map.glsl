#ifndef CAUSTICS_CAUSTIC_MAP_GLSL
#define CAUSTICS_CAUSTIC_MAP_GLSL
// The map layer is the shared dialect's common/caustic_map.h.
#include "common/caustic_map.h"

// Does layer m own scene instance `instance`? (common/caustic_map.h, causticLayerOwnsEntry.)
#define CAUSTIC_LAYER_OWNS(owners, m, instanceCount, instance) \
    causticLayerOwnsEntry((m), owners[(m).ownerRow * (instanceCount) + (instance)])
#endif
