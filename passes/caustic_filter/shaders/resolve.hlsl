// D3D12 entry of caustics.resolve; the body is resolve.h (docs/shaders.md).
#include "resolve.h"
[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) { resolveThread(id.xy); }
