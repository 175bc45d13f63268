#ifndef CAUSTICS_PASS_DIRECT_H
#define CAUSTICS_PASS_DIRECT_H
// direct_lighting in the shared dialect (the paper's section 3.1 "global illumination" step;
// docs/shaders.md): one launch per pixel reads the G-buffer and sums every light with a ray-traced
// shadow. Pixels whose surface is specular follow their reflected and refracted lobes
// (traceSpecularChain) to the first diffuse surfaces and show their direct light, weighted by the
// path's Fresnel/transmission throughput: the "transparencies and reflections" of section 3.1.
// Caustic light (light -> specular -> diffuse) is not here: that is the caustic passes' output.
// Entries: direct.rgen, surface.rchit, surface.rmiss, shadow.rmiss and their .hlsl. GLSL and HLSL only:
// direct_light.h holds the pure functions C++ compiles.
#include "common/bsdf.h"
#include "common/camera.h"
#include "common/resources.h"
#include "common/view_lobes.h"
#include "direct_light.h"

#include "bindings/direct_lighting.h"   // generated from passes/direct_lighting/direct_lighting_bindings.h

// A camera path at a specular surface follows both lobes (reflection and refraction, weighted by
// Fresnel: common/view_lobes.h) for its first kSplitEvents events, then only the stronger one, up to
// kMaxSpecularChain events: glass shows its reflection and what lies behind it, deterministically
// (docs/caustics.md "Direct light through glass"). At most 2^kSplitEvents branches per pixel.
CAUSTICS_CONST uint kMaxSpecularChain = 8u;
CAUSTICS_CONST uint kSplitEvents = 3u;
CAUSTICS_CONST float kMinBranchWeight = 1.0e-3f;   // branches weaker than this are dropped

// The two traces, per API: a surface ray (hit group 0, miss 0) and a shadow ray (miss 1, any hit ends it).
#if defined(CAUSTICS_LANG_GLSL)
layout(location = 0) rayPayloadEXT SurfacePayload surface;
layout(location = 1) rayPayloadEXT ShadowPayload shadow;
SurfacePayload traceSurface(float3 origin, float3 dir) {
    surface.instance = ~0u;
    traceRayEXT(sceneTlas, gl_RayFlagsOpaqueEXT, 0xFF, 0, 1, 0, origin, 0.0f, dir, 1.0e6f, 0);
    return surface;
}
float traceShadow(float3 origin, float3 dir, float tMax) {
    shadow.unoccluded = 0u;
    traceRayEXT(sceneTlas, gl_RayFlagsTerminateOnFirstHitEXT | gl_RayFlagsOpaqueEXT | gl_RayFlagsSkipClosestHitShaderEXT,
                0xFF, 0, 1, 1, origin, 0.0f, dir, tMax, 1);
    return float(shadow.unoccluded);
}
#else
SurfacePayload traceSurface(float3 origin, float3 dir) {
    RayDesc ray;
    ray.Origin = origin;
    ray.TMin = 0.0f;
    ray.Direction = dir;
    ray.TMax = 1.0e6f;
    SurfacePayload surface;
    surface.instance = ~0u;
    surface.primitive = 0u;
    surface.barycentrics = (float2)0.0f;
    TraceRay(sceneTlas, RAY_FLAG_FORCE_OPAQUE, 0xFF, 0, 1, 0, ray, surface);
    return surface;
}
float traceShadow(float3 origin, float3 dir, float tMax) {
    RayDesc ray;
    ray.Origin = origin;
    ray.TMin = 0.0f;
    ray.Direction = dir;
    ray.TMax = tMax;
    ShadowPayload shadow;
    shadow.unoccluded = 0u;
    TraceRay(sceneTlas, RAY_FLAG_ACCEPT_FIRST_HIT_AND_END_SEARCH | RAY_FLAG_FORCE_OPAQUE | RAY_FLAG_SKIP_CLOSEST_HIT_SHADER,
             0xFF, 0, 1, 1, ray, shadow);
    return float(shadow.unoccluded);
}
#endif

// 1 when nothing (diffuse or specular: light through glass is the caustic passes' job) lies between
// p and the light. The origin is offset along the normal by the float spacing of p.
float shadowVisibility(float3 p, float3 n, float3 toLight, float distance) {
    float eps = surfaceOffset(p);
    return traceShadow(p + n * eps, toLight, max(distance - 2.0f * eps, 0.0f));
}

// Outgoing radiance towards v of a surface point lit by every scene light: sum of
// f_r(l, v) E_l cos(theta_l) V_l with the one glTF BRDF of shaders/common/bsdf.h (docs/physics.md,
// "One BSDF"), the same one the caustic splat and gather evaluate.
// diffuseOnly: the BRDF's diffuse term alone (evalGltfDiffuse: a specular material's base seen through glass).
float3 shadeDirectBrdf(float3 p, float3 n, float3 v, BrdfMaterial brdf, bool diffuseOnly) {
    float3 result = splat3(0.0f);
    uint count = sceneLightCount();
    for (uint i = 0u; i < count; ++i) {
        LightSample s = sampleLight(sceneLight(i), p);
        float nl = dot(n, s.toLight);
        if (nl <= 0.0f || max(s.irradiance.r, max(s.irradiance.g, s.irradiance.b)) <= 0.0f) continue;
        float3 f = diffuseOnly ? evalGltfDiffuse(brdf, n, s.toLight, v) : evalGltfBrdf(brdf, n, s.toLight, v);
        if (max(f.r, max(f.g, f.b)) <= 0.0f) continue;
        result += f * s.irradiance * (nl * shadowVisibility(p, n, s.toLight, s.distance));
    }
    return result;
}

float3 shadeMaterial(float3 p, float3 n, float3 v, float3 albedo, GpuMaterial m, bool diffuseOnly) {
    return shadeDirectBrdf(p, n, v, makeBrdfMaterial(albedo, m.metallic, m.roughness, m.transmission,
                                                     gltfDielectricF0(m.specular, m.ior)), diffuseOnly);
}

struct ChainBranch {
    float3 origin;
    float3 direction;
    float3 weight;
    uint events;
};

ChainBranch makeBranch(float3 p, float3 n, float3 direction, float3 weight, uint events) {
    // Leave on the side the new direction points to, offset by the float spacing of p.
    ChainBranch b;
    b.origin = p + (dot(direction, n) > 0.0f ? n : -n) * surfaceOffset(p);
    b.direction = direction;
    b.weight = weight;
    b.events = events;
    return b;
}

// Direct light seen through the specular surface at p (shading normal n facing -d, material m) by a
// path arriving along d: the sum over the chain's branches of weight x the direct light (BRDF of
// shaders/common/bsdf.h) at the first diffuse surface, plus the specular highlights met on the way.
float3 traceSpecularChain(float3 p, float3 n, float3 d, GpuMaterial m, float3 albedo, bool entering) {
    ChainBranch stack[kSplitEvents + 1u];
    uint top = 0u;
    float3 radiance = splat3(0.0f);
    float3 weight = splat3(1.0f);
    uint events = 0u;
    for (uint guard = 0u; guard < kMaxSpecularChain << kSplitEvents; ++guard) {
        bool thin = (m.flags & kMaterialThinWalled) != 0u;
        ViewLobes l = specularViewLobes(d, n, albedo, m.metallic, m.transmission, m.ior, thin, entering);
        float3 wr = weight * l.reflectWeight;
        float3 wt = weight * l.refractWeight;
        ++events;
        bool split = events <= kSplitEvents && maxComponent(wr) >= kMinBranchWeight && maxComponent(wt) >= kMinBranchWeight;
        if (split) stack[top++] = makeBranch(p, n, l.reflectDirection, wr, events);
        bool refract = split || maxComponent(wt) > maxComponent(wr);
        // Two calls, not a ?: between structs (DXC rejects struct operands of ?:; docs/d3d12.md).
        ChainBranch b;
        if (refract) b = makeBranch(p, n, l.refractDirection, wt, events);
        else b = makeBranch(p, n, l.reflectDirection, wr, events);
        for (;;) {
            SurfaceHit h;
            bool hit = false;
            if (maxComponent(b.weight) >= kMinBranchWeight && b.events <= kMaxSpecularChain) {
                SurfacePayload surface = traceSurface(b.origin, b.direction);
                hit = surface.instance != ~0u;
                if (hit) h = sceneSurfaceHit(surface.instance, surface.primitive, surface.barycentrics);
            }
            if (hit) {
                float3 ns = h.shadingNormal;
                if (dot(ns, b.direction) > 0.0f) ns = -ns;   // face the incoming ray
                // Diffuse: its direct light ends the branch. Specular: its diffuse base's direct light
                // (zero for full metal or glass; the primary surface shows its own through the whole
                // BRDF), then scatter on. (A point light's highlight on a specular surface seen through
                // another is left out: at the clamped roughness it is a one-pixel spike, and the primary
                // surface shows its own.)
                if (!sceneMaterialIsSpecular(h.material)) {
                    radiance += b.weight * shadeMaterial(h.position, ns, -b.direction, h.baseColor, h.material, false);
                } else {
                    radiance += b.weight * shadeMaterial(h.position, ns, -b.direction, h.baseColor, h.material, true);
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
            // The branch ended (diffuse hit, miss, too weak or too long): resume a pending one.
            if (top == 0u) return radiance;
            b = stack[--top];
        }
    }
    return radiance;
}

void directThread(int2 pixel) {
    uint objectId = CAUSTICS_TEXEL_UINT(gObjectId, pixel);
    if (objectId == 0u) {
        CAUSTICS_IMAGE_STORE(outRadiance, pixel, float4(0.0f, 0.0f, 0.0f, 1.0f));
        return;
    }
    float4 nr = CAUSTICS_TEXEL(gNormalRoughness, pixel);
    float4 am = CAUSTICS_TEXEL(gAlbedoMetallic, pixel);
    float linearDepth = CAUSTICS_TEXEL(gLinearDepth, pixel).x;
    float3 p = cameraWorldPosition(camera, float2(pixel) + 0.5f, linearDepth);
    float3 n = normalize(nr.xyz);
    float3 v = normalize(toFloat3(camera.eye) - p);
    GpuMaterial m = sceneMaterial(sceneInstance(objectId - 1u).material);

    // The G-buffer's albedo/metallic/roughness win over the material table (a host G-buffer may differ).
    float3 radiance = shadeDirectBrdf(p, n, v, makeBrdfMaterial(am.rgb, am.a, nr.w, m.transmission,
                                                                gltfDielectricF0(m.specular, m.ior)), false);
    if (sceneMaterialIsSpecular(m)) radiance += traceSpecularChain(p, n, -v, m, am.rgb, true);
    CAUSTICS_IMAGE_STORE(outRadiance, pixel, float4(radiance, 1.0f));
}

#endif  // CAUSTICS_PASS_DIRECT_H
