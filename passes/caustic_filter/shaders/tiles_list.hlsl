// D3D12 entry of caustics.filterTiles for the second type in list order (common/specular_list.h;
// docs/caustics.md "Second-type memory"): tiles.hlsl with FILTER_LIST_ORDER.
#define FILTER_LIST_ORDER 1
#include "scene/camera.hlsli"
#include "tiles_thread.h"
[numthreads(8, 8, 1)]
void main(uint3 group : SV_GroupID, uint3 id : SV_DispatchThreadID, uint local : SV_GroupIndex) {
    filterTilesThread(group.xy, id.xy, local);
}
