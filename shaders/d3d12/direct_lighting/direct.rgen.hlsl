// Deferred direct lighting (paper 3.1; mirror of shaders/vulkan/direct_lighting/direct.rgen): one
// thread per pixel, every light with a ray-traced shadow; specular pixels follow their most probable
// specular lobe to the first diffuse surface.
#include "scene/scene.hlsli"
#include "scene/camera.hlsli"
#include "direct_lighting/shading.hlsli"

struct CameraBlock { CameraConstants camera; };
ConstantBuffer<CameraBlock> cameraBlock : register(b0, space1);
Texture2D<float4> gNormalRoughness : register(t0, space2);
Texture2D<float4> gAlbedoMetallic : register(t1, space2);
Texture2D<float4> gLinearDepth : register(t2, space2);
Texture2D<uint> gObjectId : register(t3, space2);
RWTexture2D<float4> outRadiance : register(u4, space2);

static const uint kMaxSpecularChain = 6u;

float3 shadeMaterial(float3 p, float3 n, float3 v, float3 albedo, GpuMaterial m) {
    return shadeDirect(p, n, v, albedo, m.metallic, m.roughness, m.transmission, m.specular, m.ior);
}

float3 traceSpecularChain(float3 p, float3 n, float3 d, GpuMaterial m, float3 albedo, bool entering) {
    float3 weight = (float3)1.0f;
    for (uint event = 0u; event < kMaxSpecularChain; ++event) {
        float cosI = max(dot(-d, n), 0.0f);
        float3 next;
        if (m.metallic > 0.5f) {
            weight *= fresnelSchlick(albedo, cosI);
            next = reflect(d, n);
        } else {
            bool thin = (m.flags & kMaterialThinWalled) != 0u;
            float eta = thin ? 1.0f : (entering ? m.ior : 1.0f / m.ior);
            float fr = fresnelDielectric(cosI, eta);
            float t = m.transmission * (1.0f - fr);
            float3 refracted;
            if (t >= fr && refractDirection(d, n, 1.0f / eta, refracted)) {
                weight *= t * albedo;
                next = thin ? d : refracted;
                n = -n;
            } else {
                weight *= max(fr, 1.0e-3f);
                next = reflect(d, n);
            }
        }
        d = normalize(next);
        float eps = 1.0e-4f * (1.0f + max(max(abs(p.x), abs(p.y)), abs(p.z)));
        RayDesc ray;
        ray.Origin = p + n * eps;
        ray.TMin = 0.0f;
        ray.Direction = d;
        ray.TMax = 1.0e6f;
        SurfacePayload surface;
        surface.instance = ~0u;
        surface.primitive = 0u;
        surface.barycentrics = (float2)0.0f;
        TraceRay(sceneTlas, RAY_FLAG_FORCE_OPAQUE, 0xFF, 0, 1, 0, ray, surface);
        if (surface.instance == ~0u) return (float3)0.0f;
        SurfaceHit h = sceneSurfaceHit(surface.instance, surface.primitive, surface.barycentrics);
        entering = dot(d, h.geometricNormal) < 0.0f;
        float3 ns = h.shadingNormal;
        if (dot(ns, d) > 0.0f) ns = -ns;
        p = h.position;
        n = ns;
        m = h.material;
        albedo = h.baseColor;
        if (!sceneMaterialIsSpecular(m)) return weight * shadeMaterial(p, n, -d, albedo, m);
    }
    return (float3)0.0f;
}

[shader("raygeneration")]
void main() {
    CameraConstants camera = cameraBlock.camera;
    int2 pixel = int2(DispatchRaysIndex().xy);
    uint objectId = gObjectId.Load(int3(pixel, 0));
    if (objectId == 0u) {
        outRadiance[pixel] = float4(0.0f, 0.0f, 0.0f, 1.0f);
        return;
    }
    float4 nr = gNormalRoughness.Load(int3(pixel, 0));
    float4 am = gAlbedoMetallic.Load(int3(pixel, 0));
    float linearDepth = gLinearDepth.Load(int3(pixel, 0)).x;
    float3 p = cameraWorldPosition(camera, float2(pixel) + 0.5f, linearDepth);
    float3 n = normalize(nr.xyz);
    float3 v = normalize(camera.eye.xyz - p);
    GpuMaterial m = sceneMaterial(sceneInstance(objectId - 1u).material);
    float3 radiance = shadeDirect(p, n, v, am.rgb, am.a, nr.w, m.transmission, m.specular, m.ior);
    if (sceneMaterialIsSpecular(m)) radiance += traceSpecularChain(p, n, -v, m, am.rgb, true);
    outRadiance[pixel] = float4(radiance, 1.0f);
}
