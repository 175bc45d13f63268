// D3D12 entry of caustics.filterOutput for the second type in list order (common/specular_list.h;
// docs/caustics.md "Second-type memory"): output.hlsl with FILTER_LIST_ORDER.
#define FILTER_LIST_ORDER 1
#include "output.h"
[numthreads(8, 8, 1)]
void main(uint3 group : SV_GroupID, uint3 local : SV_GroupThreadID) { filterOutputThread(group.x, local.xy); }
