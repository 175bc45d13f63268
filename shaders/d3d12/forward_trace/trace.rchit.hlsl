// Closest hit of every caustic trace: returns instance, primitive, barycentrics, t; the raygen does
// the shading (mirror of shaders/vulkan/forward_trace/trace.rchit).
#include "forward_trace/caustic_hit.hlsli"

[shader("closesthit")]
void main(inout TracePayload payload, in BuiltInTriangleIntersectionAttributes attribs) {
    payload.barycentrics = attribs.barycentrics;
    payload.instance = InstanceID();
    payload.primitive = PrimitiveIndex();
    payload.t = RayTCurrent();
}
