// D3D12 entry of caustics.forward with 32-bit fixed-point atomics (devices without float atomics); the body is forward.h (docs/shaders.md).
#define CAUSTICS_FIXED_POINT
#include "common/scene_resources.h"
#include "forward.h"
[shader("raygeneration")]
void main() { forwardLaunch(DispatchRaysIndex().x, DispatchRaysDimensions().x); }
