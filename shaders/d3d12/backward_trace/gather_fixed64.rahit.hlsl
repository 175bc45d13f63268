// Gather any-hit, 64-bit fixed-point radiance (SM 6.6 InterlockedAdd64).
#define CAUSTICS_FIXED_POINT_64
#include "backward_trace/gather_body.hlsli"
