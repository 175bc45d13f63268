// D3D12 entry of the filter's combine pass for the second type in list order (common/specular_list.h;
// docs/caustics.md "Second-type memory"): combine_types.hlsl with FILTER_LIST_ORDER.
#define FILTER_LIST_ORDER 1
#include "combine_types.h"
[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) { combineTypesThread(id.xy); }
