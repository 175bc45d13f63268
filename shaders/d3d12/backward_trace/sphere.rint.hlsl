// One AABB per backward hit, its primitive index the sphere's slot (mirror of
// shaders/vulkan/backward_trace/sphere.rint): the ray origin (a stored forward hit) is reported when it
// lies in the sphere's gather disk (common/gather_disk.h). Slots no sphere was written to hold a point
// box at the origin and are refused.
#include "common/gather_disk.h"
#include "forward_trace/caustic_hit.hlsli"
#include "backward_trace/gather_payload.hlsli"
#include "backward_trace/sphere_list.hlsli"
ByteAddressBuffer spheres : register(t1, space0);
RWByteAddressBuffer stats : register(u3, space0);

[shader("intersection")]
void main() {
    if (PrimitiveIndex() >= min(stats.Load(4u * kStatSpheres), stats.Load(4u * kStatSphereCapacity))) return;
    CausticSphere s = loadCausticSphere(spheres, PrimitiveIndex());
    if (insideGatherDisk(WorldRayOrigin(), s.centre, s.normal, s.radius)) {
        SphereAttributes attribs;
        attribs.unused = (float2)0.0f;
        ReportHit(RayTMin(), 0u, attribs);
    }
}
