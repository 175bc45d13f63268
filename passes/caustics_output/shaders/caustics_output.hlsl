// D3D12 entries of caustics_output; the body is caustics_output.h (docs/shaders.md).
#include "caustics_output.h"

#if defined(CAUSTICS_STAGE_VERT)
// Non-indexed draw of 3 vertices: SV_VertexID counts 0, 1, 2 like gl_VertexIndex.
float4 main(uint vertexIndex : SV_VertexID) : SV_Position { return fullScreenTriangleVertex(vertexIndex); }
#elif defined(CAUSTICS_STAGE_FRAG)
float4 main(float4 position : SV_Position) : SV_Target0 { return causticsOutputFragment(position); }
#endif
