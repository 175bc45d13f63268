// Shadow rays skip closest-hit shaders; only a miss (nothing between the point and the light) runs
// (mirror of shaders/vulkan/direct_lighting/shadow.rmiss).
#include "direct_lighting/payloads.hlsli"

[shader("miss")]
void main(inout ShadowPayload payload) { payload.unoccluded = 1u; }
