// Unit-sphere AABB instanced per backward hit (mirror of shaders/vulkan/backward_trace/sphere.rint):
// the ray origin (a stored forward hit) lies inside when |o - c|^2 < r^2 in world space.
#include "forward_trace/caustic_hit.hlsli"
#include "backward_trace/gather_payload.hlsli"
ByteAddressBuffer spheres : register(t1, space0);

[shader("intersection")]
void main() {
    CausticSphere s = loadCausticSphere(spheres, InstanceIndex());
    float3 d = WorldRayOrigin() - s.centre;
    if (dot(d, d) < s.radius * s.radius) {
        SphereAttributes attribs;
        attribs.unused = (float2)0.0f;
        ReportHit(RayTMin(), 0u, attribs);
    }
}
