// D3D12 entry of the composite pass; the body is composite.h (docs/shaders.md).
#include "composite.h"
[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) { compositeThread(id.xy); }
