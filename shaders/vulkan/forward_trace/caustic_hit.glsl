#ifndef CAUSTICS_CAUSTIC_HIT_GLSL
#define CAUSTICS_CAUSTIC_HIT_GLSL
// The stored hit, the sphere, the trace payload and the statistics slots are the shared dialect's
// common/caustic_hit.h; this include stays for the backward pass's shaders.
#include "common/caustic_hit.h"
#endif
