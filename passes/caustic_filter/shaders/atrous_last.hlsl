// D3D12 entry of the last caustics.atrous.N (pool to caustics.radiance); the body is atrous.h (docs/shaders.md).
#define kAtrousLast 1
#include "atrous.h"
[numthreads(64, 1, 1)]
void main(uint3 group : SV_GroupID, uint local : SV_GroupIndex) { atrousThread(group.x, local); }
