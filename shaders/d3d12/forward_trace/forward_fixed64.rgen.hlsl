// Forward trace with 64-bit fixed-point atomics (SM 6.6 InterlockedAdd64).
#define CAUSTICS_FIXED_POINT_64
#include "forward_trace/forward_body.hlsli"
