// D3D12 entry of the object-id remap pass; the body is remap_object_ids.h (docs/shaders.md).
#include "remap_object_ids.h"
[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) { remapObjectIdsThread(id.xy); }
