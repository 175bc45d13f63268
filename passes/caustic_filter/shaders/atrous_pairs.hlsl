// D3D12 entry of caustics.atrous.N.pairs (12 packed pair weights per pixel); the body is atrous.h (docs/shaders.md).
#define kAtrousPairs 1
#include "atrous.h"
[numthreads(64, 1, 1)]
void main(uint3 group : SV_GroupID, uint local : SV_GroupIndex) { atrousThread(group.x, local); }
