// D3D12 entry of caustics.backward; the body is backward.h (docs/shaders.md).
#include "common/scene_resources.h"
#include "backward.h"
[shader("raygeneration")]
void main() { backwardLaunch(DispatchRaysIndex().x, DispatchRaysDimensions().x); }
