// D3D12 ray-generation entry of direct_lighting; the body is direct.h (docs/shaders.md).
#include "common/scene_resources.h"
#include "direct.h"
[shader("raygeneration")]
void main() { directThread(int2(DispatchRaysIndex().xy)); }
