// D3D12 entry of caustics.atrous.N.select; the body is atrous_select.h (docs/shaders.md).
#include "atrous_select.h"
[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) { atrousSelectThread(id.x); }
