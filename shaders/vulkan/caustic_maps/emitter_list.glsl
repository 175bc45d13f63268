#ifndef CAUSTICS_EMITTER_LIST_GLSL
#define CAUSTICS_EMITTER_LIST_GLSL
// The emitter list's packing is the shared dialect's common/caustic_map.h, the statistics slots
// common/caustic_stats.h.
#include "common/caustic_map.h"
#include "common/caustic_stats.h"
#endif
