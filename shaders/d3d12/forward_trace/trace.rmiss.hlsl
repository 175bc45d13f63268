// Miss of the caustic traces (mirror of shaders/vulkan/forward_trace/trace.rmiss).
#include "forward_trace/caustic_hit.hlsli"

[shader("miss")]
void main(inout TracePayload payload) { payload.t = -1.0f; }
