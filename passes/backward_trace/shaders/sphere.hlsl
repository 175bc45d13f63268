// D3D12 intersection of caustics.gather (one AABB per sphere slot); the body is gather.h (docs/shaders.md).
#include "gather.h"
struct SphereAttributes { float2 unused; };   // 8 bytes, within maxAttributeBytes
[shader("intersection")]
void main() {
    if (!gatherSphereContains(PrimitiveIndex(), WorldRayOrigin())) return;
    SphereAttributes attribs;
    attribs.unused = float2(0.0f, 0.0f);
    ReportHit(RayTMin(), 0u, attribs);
}
