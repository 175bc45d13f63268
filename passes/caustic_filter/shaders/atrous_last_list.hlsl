// D3D12 entry of the last caustics.atrous.N for the second type in list order (common/specular_list.h;
// docs/caustics.md "Second-type memory"): atrous_last.hlsl with FILTER_LIST_ORDER.
#define FILTER_LIST_ORDER 1
#define kAtrousLast 1
#include "atrous.h"
[numthreads(64, 1, 1)]
void main(uint3 group : SV_GroupID, uint local : SV_GroupIndex) { atrousThread(group.x, local); }
