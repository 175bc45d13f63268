// D3D12 entry of caustics.atrous.N before the last (pool to pool); the body is atrous.h (docs/shaders.md).
#include "atrous.h"
[numthreads(64, 1, 1)]
void main(uint3 group : SV_GroupID, uint local : SV_GroupIndex) { atrousThread(group.x, local); }
