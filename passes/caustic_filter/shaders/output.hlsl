// D3D12 entry of caustics.filterOutput; the body is output.h (docs/shaders.md).
#include "output.h"
[numthreads(8, 8, 1)]
void main(uint3 group : SV_GroupID, uint3 local : SV_GroupThreadID) { filterOutputThread(group.x, local.xy); }
