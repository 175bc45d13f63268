// Miss of the gather rays: nothing to do (mirror of shaders/vulkan/backward_trace/gather.rmiss).
#include "backward_trace/gather_payload.hlsli"

[shader("miss")]
void main(inout GatherPayload payload) {}
