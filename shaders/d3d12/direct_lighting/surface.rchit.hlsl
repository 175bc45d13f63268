// Closest hit of the direct-lighting surface rays (mirror of shaders/vulkan/direct_lighting/surface.rchit).
#include "direct_lighting/payloads.hlsli"

[shader("closesthit")]
void main(inout SurfacePayload payload, in BuiltInTriangleIntersectionAttributes attribs) {
    payload.instance = InstanceID();
    payload.primitive = PrimitiveIndex();
    payload.barycentrics = attribs.barycentrics;
}
