// D3D12 any-hit of caustics.gather with 32-bit fixed-point radiance: gather.hlsl's (docs/shaders.md).
#define CAUSTICS_FIXED_POINT
#include "gather.hlsl"
