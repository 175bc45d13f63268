// D3D12 entry of caustics.specularPixels; the body is specular_pixels.h (docs/shaders.md).
#include "specular_pixels.h"
[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID, uint3 group : SV_GroupID, uint local : SV_GroupIndex) {
    specularPixelsThread(id.xy, group.xy, local);
}
