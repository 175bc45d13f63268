// D3D12 entry of caustics.variance; the body is variance.h (docs/shaders.md).
#include "variance.h"
[numthreads(8, 8, 1)]
void main(uint3 group : SV_GroupID, uint3 local : SV_GroupThreadID) { varianceThread(group.x, local.xy); }
