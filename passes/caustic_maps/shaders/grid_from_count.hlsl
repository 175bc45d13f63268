// D3D12 entry of the grid-from-count pass; the body is grid_from_count.h (docs/shaders.md).
#include "grid_from_count.h"
[numthreads(1, 1, 1)]
void main() { writeGridFromCount(params); }
