#ifndef CAUSTICS_SPHERE_LIST_GLSL
#define CAUSTICS_SPHERE_LIST_GLSL
// Statistics slots of the second type's cost: now named once, with every slot, in common/caustic_stats.h.
#include "common/caustic_stats.h"
#endif
