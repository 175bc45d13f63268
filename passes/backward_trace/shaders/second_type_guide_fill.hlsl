// D3D12 entry of the second-type guide fill pass; the body is second_type_guide_fill.h (docs/shaders.md).
#include "second_type_guide_fill.h"
[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) { secondTypeGuideFillThread(id.xy); }
