// D3D12 entry of the second-type guide pass; the body is second_type_guides.h (docs/shaders.md).
#include "second_type_guides.h"
[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) { secondTypeGuidesThread(id.xy); }
