#version 460
// A host engine's own G-buffer pass (tests/gpu/embedding/host_engine_test.cpp): no rasterizer, no ray
// tracing. One camera ray per pixel centre, intersected with every world-space triangle of the scene
// (Moller-Trumbore), written in the module's G-buffer contract (passes/include/caustics/gbuffer.h):
// normal (interpolated, facing the viewer) + roughness, linear albedo + metallic, optics, linear depth
// along the camera axis, objectId = the host's id of the instance, idBase + idStride * instance index
// (1 + 1 * index: the module's own ids). Background: all zero.
layout(local_size_x = 8, local_size_y = 8) in;

struct Triangle {
    vec4 p0, p1, p2;   // world positions; p0.w = instance index
    vec4 n0, n1, n2;   // world vertex normals
};
struct InstanceLook {
    vec4 albedoMetallic;   // linear base colour, metallic
    vec4 optics;           // gbuffer.h encoding
    vec4 roughness;        // x
};
layout(std430, set = 0, binding = 0) readonly buffer Triangles { Triangle triangles[]; };
layout(std430, set = 0, binding = 1) readonly buffer Instances { InstanceLook instances[]; };
layout(set = 0, binding = 2, rgba16f) uniform writeonly image2D normalRoughness;
layout(set = 0, binding = 3, rgba8) uniform writeonly image2D albedoMetallic;
layout(set = 0, binding = 4, rgba16f) uniform writeonly image2D optics;
layout(set = 0, binding = 5, r32f) uniform writeonly image2D linearDepth;
layout(set = 0, binding = 6, r32ui) uniform writeonly uimage2D objectId;

layout(push_constant) uniform Camera {
    mat4 invViewProj;   // Vulkan clip (y down, z 0..1) -> world
    vec4 eye;           // xyz; w = triangle count
    vec4 forward;       // xyz camera axis
    vec4 size;          // xy width, height; zw idBase, idStride
} cam;

void main() {
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    const vec2 size = cam.size.xy;
    if (p.x >= int(size.x) || p.y >= int(size.y)) return;
    // The rasterizer samples pixel centres; NDC y grows downwards like the framebuffer's rows.
    const vec2 ndc = (vec2(p) + 0.5) / size * 2.0 - 1.0;
    const vec4 nearPoint = cam.invViewProj * vec4(ndc, 0.0, 1.0);
    const vec4 farPoint = cam.invViewProj * vec4(ndc, 1.0, 1.0);
    const vec3 origin = cam.eye.xyz;
    const vec3 dir = normalize(farPoint.xyz / farPoint.w - nearPoint.xyz / nearPoint.w);

    float bestT = 1.0e30;
    int best = -1;
    vec2 bestUv = vec2(0.0);
    const int count = int(cam.eye.w);
    for (int i = 0; i < count; ++i) {
        const vec3 e1 = triangles[i].p1.xyz - triangles[i].p0.xyz;
        const vec3 e2 = triangles[i].p2.xyz - triangles[i].p0.xyz;
        const vec3 h = cross(dir, e2);
        const float det = dot(e1, h);
        if (abs(det) < 1e-12) continue;
        const vec3 s = origin - triangles[i].p0.xyz;
        const float u = dot(s, h) / det;
        if (u < 0.0 || u > 1.0) continue;
        const vec3 q = cross(s, e1);
        const float v = dot(dir, q) / det;
        if (v < 0.0 || u + v > 1.0) continue;
        const float t = dot(e2, q) / det;
        if (t > 0.0 && t < bestT) { bestT = t; best = i; bestUv = vec2(u, v); }
    }
    if (best < 0) {
        imageStore(normalRoughness, p, vec4(0.0));
        imageStore(albedoMetallic, p, vec4(0.0));
        imageStore(optics, p, vec4(0.0));
        imageStore(linearDepth, p, vec4(0.0));
        imageStore(objectId, p, uvec4(0u));
        return;
    }
    const Triangle tri = triangles[best];
    const uint instance = uint(tri.p0.w);
    const vec3 hit = origin + bestT * dir;
    vec3 n = (1.0 - bestUv.x - bestUv.y) * tri.n0.xyz + bestUv.x * tri.n1.xyz + bestUv.y * tri.n2.xyz;
    if (dot(n, n) < 1e-12) n = cross(tri.p1.xyz - tri.p0.xyz, tri.p2.xyz - tri.p0.xyz);
    n = normalize(n);
    if (dot(n, origin - hit) < 0.0) n = -n;
    const InstanceLook look = instances[instance];
    imageStore(normalRoughness, p, vec4(n, look.roughness.x));
    imageStore(albedoMetallic, p, look.albedoMetallic);
    imageStore(optics, p, look.optics);
    imageStore(linearDepth, p, vec4(dot(hit - origin, cam.forward.xyz)));
    imageStore(objectId, p, uvec4(uint(cam.size.z) + uint(cam.size.w) * instance));
}
