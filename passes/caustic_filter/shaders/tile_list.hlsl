// D3D12 entry of caustics.filterTiles.list; the body is tiles.h (docs/shaders.md).
#include "tile_list_thread.h"
[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) { tileListThread(id.xy); }
