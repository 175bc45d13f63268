// D3D12 entry of caustics.filterTiles; the body is tiles.h (docs/shaders.md).
#include "scene/camera.hlsli"
#include "tiles_thread.h"
[numthreads(8, 8, 1)]
void main(uint3 group : SV_GroupID, uint3 id : SV_DispatchThreadID, uint local : SV_GroupIndex) {
    filterTilesThread(group.xy, id.xy, local);
}
