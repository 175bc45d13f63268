#ifndef CAUSTICS_LAYER_PLAN_GLSL
#define CAUSTICS_LAYER_PLAN_GLSL
// The layer plan of the passes not yet moved (docs/shaders.md): the shared-dialect struct.
#include "common/layer_plan.h"
#endif
