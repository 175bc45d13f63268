// D3D12 entry of caustics.temporal for the second type in list order (common/specular_list.h;
// docs/caustics.md "Second-type memory"): temporal.hlsl with FILTER_LIST_ORDER.
#define FILTER_LIST_ORDER 1
#include "scene/camera.hlsli"
#include "temporal.h"
[numthreads(8, 8, 1)]
void main(uint3 group : SV_GroupID, uint3 local : SV_GroupThreadID) { temporalThread(group.x, local.xy); }
