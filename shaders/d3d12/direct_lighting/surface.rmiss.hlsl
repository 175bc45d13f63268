// Miss of the surface rays (mirror of shaders/vulkan/direct_lighting/surface.rmiss).
#include "direct_lighting/payloads.hlsli"

[shader("miss")]
void main(inout SurfacePayload payload) { payload.instance = ~0u; }
