// D3D12 any-hit of caustics.gather with 64-bit fixed-point radiance: gather.hlsl's (docs/shaders.md).
#define CAUSTICS_FIXED_POINT_64
#include "gather.hlsl"
