// D3D12 entry of caustics.emitters; the body is emitters.h (docs/shaders.md).
#define SCENE_NO_TEXTURES
#define SCENE_NO_TLAS
#include "common/scene_resources.h"
#include "emitters.h"
[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) { emittersThread(id); }
