// D3D12 closest hit and miss of direct_lighting's surface rays (surface.rchit, surface.rmiss).
#include "direct_light.h"
#if defined(CAUSTICS_STAGE_RCHIT)
[shader("closesthit")]
void main(inout SurfacePayload payload, in BuiltInTriangleIntersectionAttributes attribs) {
    payload.instance = InstanceID();
    payload.primitive = PrimitiveIndex();
    payload.barycentrics = attribs.barycentrics;
}
#elif defined(CAUSTICS_STAGE_RMISS)
[shader("miss")]
void main(inout SurfacePayload payload) { payload.instance = ~0u; }
#endif
