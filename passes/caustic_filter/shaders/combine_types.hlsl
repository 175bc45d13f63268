// D3D12 entry of the filter's combine pass; the body is combine_types.h (docs/shaders.md).
#include "combine_types.h"
[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) { combineTypesThread(id.xy); }
