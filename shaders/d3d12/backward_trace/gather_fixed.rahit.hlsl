// Gather any-hit, fixed-point radiance.
#define CAUSTICS_FIXED_POINT
#include "backward_trace/gather_body.hlsli"
