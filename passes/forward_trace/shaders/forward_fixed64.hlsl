// D3D12 entry of caustics.forward with 64-bit fixed-point atomics (no float atomics, shaderBufferInt64Atomics); the body is forward.h (docs/shaders.md).
#define CAUSTICS_FIXED_POINT_64
#include "common/scene_resources.h"
#include "forward.h"
[shader("raygeneration")]
void main() { forwardLaunch(DispatchRaysIndex().x, DispatchRaysDimensions().x); }
