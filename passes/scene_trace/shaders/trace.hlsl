// D3D12 closest hit and miss of every scene trace (trace.rchit, trace.rmiss; forward.h traceScene).
#include "common/caustic_hit.h"
#if defined(CAUSTICS_STAGE_RCHIT)
[shader("closesthit")]
void main(inout TracePayload payload, in BuiltInTriangleIntersectionAttributes attribs) {
    payload.barycentrics = attribs.barycentrics;
    payload.instance = InstanceID();
    payload.primitive = PrimitiveIndex();
    payload.t = RayTCurrent();
}
#elif defined(CAUSTICS_STAGE_RMISS)
[shader("miss")]
void main(inout TracePayload payload) { payload.t = -1.0f; }
#endif
