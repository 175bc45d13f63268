// Deferred direct lighting (paper 3.1; mirror of shaders/vulkan/direct_lighting/direct.rgen): one
// thread per pixel, every light with a ray-traced shadow; specular pixels follow their reflected and
// refracted lobes (split for the first events) to the first diffuse surfaces.
#include "scene/scene.hlsli"
#include "scene/camera.hlsli"
#include "direct_lighting/shading.hlsli"
#include "common/view_lobes.h"

struct CameraBlock { CameraConstants camera; };
ConstantBuffer<CameraBlock> cameraBlock : register(b0, space1);
Texture2D<float4> gNormalRoughness : register(t0, space2);
Texture2D<float4> gAlbedoMetallic : register(t1, space2);
Texture2D<float4> gLinearDepth : register(t2, space2);
Texture2D<uint> gObjectId : register(t3, space2);
RWTexture2D<float4> outRadiance : register(u4, space2);

// Both lobes for the first kSplitEvents events, then the stronger one (see the GLSL twin).
static const uint kMaxSpecularChain = 8u;
static const uint kSplitEvents = 3u;
static const float kMinBranchWeight = 1.0e-3f;

float3 shadeMaterial(float3 p, float3 n, float3 v, float3 albedo, GpuMaterial m) {
    return shadeDirect(p, n, v, makeBrdfMaterial(albedo, m.metallic, m.roughness, m.transmission,
                                                 gltfDielectricF0(m.specular, m.ior)));
}

struct ChainBranch { float3 origin; float3 direction; float3 weight; uint events; };

ChainBranch makeBranch(float3 p, float3 n, float3 direction, float3 weight, uint events) {
    float eps = 1.0e-4f * (1.0f + max(max(abs(p.x), abs(p.y)), abs(p.z)));
    ChainBranch b;
    b.origin = p + (dot(direction, n) > 0.0f ? n : -n) * eps;
    b.direction = direction;
    b.weight = weight;
    b.events = events;
    return b;
}

float3 traceSpecularChain(float3 p, float3 n, float3 d, GpuMaterial m, float3 albedo, bool entering) {
    ChainBranch stack[kSplitEvents + 1u];
    uint top = 0u;
    float3 radiance = (float3)0.0f;
    float3 weight = (float3)1.0f;
    uint events = 0u;
    for (uint guard = 0u; guard < (kMaxSpecularChain << kSplitEvents); ++guard) {
        bool thin = (m.flags & kMaterialThinWalled) != 0u;
        ViewLobes l = specularViewLobes(d, n, albedo, m.metallic, m.transmission, m.ior, thin, entering);
        float3 wr = weight * l.reflectWeight, wt = weight * l.refractWeight;
        ++events;
        bool split = events <= kSplitEvents && maxComponent(wr) >= kMinBranchWeight && maxComponent(wt) >= kMinBranchWeight;
        if (split) stack[top++] = makeBranch(p, n, l.reflectDirection, wr, events);
        bool refract = split || maxComponent(wt) > maxComponent(wr);
        // if/else, not ?: (DXC takes only scalar, vector or matrix operands there; docs/d3d12.md).
        ChainBranch b;
        if (refract) b = makeBranch(p, n, l.refractDirection, wt, events);
        else b = makeBranch(p, n, l.reflectDirection, wr, events);
        for (;;) {
            SurfaceHit h = (SurfaceHit)0;
            bool hit = false;
            if (maxComponent(b.weight) >= kMinBranchWeight && b.events <= kMaxSpecularChain) {
                RayDesc ray;
                ray.Origin = b.origin;
                ray.TMin = 0.0f;
                ray.Direction = b.direction;
                ray.TMax = 1.0e6f;
                SurfacePayload surface;
                surface.instance = ~0u;
                surface.primitive = 0u;
                surface.barycentrics = (float2)0.0f;
                TraceRay(sceneTlas, RAY_FLAG_FORCE_OPAQUE, 0xFF, 0, 1, 0, ray, surface);
                hit = surface.instance != ~0u;
                if (hit) h = sceneSurfaceHit(surface.instance, surface.primitive, surface.barycentrics);
            }
            if (hit) {
                float3 ns = h.shadingNormal;
                if (dot(ns, b.direction) > 0.0f) ns = -ns;
                if (!sceneMaterialIsSpecular(h.material)) {
                    radiance += b.weight * shadeMaterial(h.position, ns, -b.direction, h.baseColor, h.material);
                } else {
                    p = h.position;
                    n = ns;
                    d = b.direction;
                    m = h.material;
                    albedo = h.baseColor;
                    entering = dot(d, h.geometricNormal) < 0.0f;
                    weight = b.weight;
                    events = b.events;
                    break;
                }
            }
            if (top == 0u) return radiance;
            b = stack[--top];
        }
    }
    return radiance;
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
    float3 radiance = shadeDirect(p, n, v, makeBrdfMaterial(am.rgb, am.a, nr.w, m.transmission,
                                                                gltfDielectricF0(m.specular, m.ior)));
    if (sceneMaterialIsSpecular(m)) radiance += traceSpecularChain(p, n, -v, m, am.rgb, true);
    outRadiance[pixel] = float4(radiance, 1.0f);
}
