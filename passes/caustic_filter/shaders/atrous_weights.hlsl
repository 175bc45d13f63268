// D3D12 entry of caustics.atrous.N.weights (W_q per pixel); the body is atrous.h (docs/shaders.md).
#define kAtrousWeights 1
#include "atrous.h"
[numthreads(64, 1, 1)]
void main(uint3 group : SV_GroupID, uint local : SV_GroupIndex) { atrousThread(group.x, local); }
