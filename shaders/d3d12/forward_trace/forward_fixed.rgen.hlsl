// Forward trace with fixed-point atomics.
#define CAUSTICS_FIXED_POINT
#include "forward_trace/forward_body.hlsli"
