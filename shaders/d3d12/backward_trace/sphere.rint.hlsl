// Unit-sphere AABB instanced per backward hit (mirror of shaders/vulkan/backward_trace/sphere.rint):
// the ray origin (a stored forward hit) is reported when it lies in the sphere's gather disk
// (common/gather_disk.h).
#include "common/gather_disk.h"
#include "forward_trace/caustic_hit.hlsli"
#include "backward_trace/gather_payload.hlsli"
ByteAddressBuffer spheres : register(t1, space0);

[shader("intersection")]
void main() {
    CausticSphere s = loadCausticSphere(spheres, InstanceIndex());
    if (insideGatherDisk(WorldRayOrigin(), s.centre, s.normal, s.radius)) {
        SphereAttributes attribs;
        attribs.unused = (float2)0.0f;
        ReportHit(RayTMin(), 0u, attribs);
    }
}
