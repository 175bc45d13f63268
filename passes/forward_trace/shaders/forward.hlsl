// D3D12 entry of caustics.forward with float atomics (GL_EXT_shader_atomic_float); the body is forward.h (docs/shaders.md).
#include "common/scene_resources.h"
#include "forward.h"
[shader("raygeneration")]
void main() { forwardLaunch(DispatchRaysIndex().x, DispatchRaysDimensions().x); }
