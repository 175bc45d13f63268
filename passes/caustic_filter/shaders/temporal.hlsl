// D3D12 entry of caustics.temporal; the body is temporal.h (docs/shaders.md).
#include "scene/camera.hlsli"
#include "temporal.h"
[numthreads(8, 8, 1)]
void main(uint3 group : SV_GroupID, uint3 local : SV_GroupThreadID) { temporalThread(group.x, local.xy); }
