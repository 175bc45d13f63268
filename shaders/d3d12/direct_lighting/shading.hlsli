#ifndef CAUSTICS_D3D12_DIRECT_SHADING_HLSLI
#define CAUSTICS_D3D12_DIRECT_SHADING_HLSLI
// Direct illumination with ray-traced shadows (mirror of shaders/vulkan/direct_lighting/shading.glsl).
// Needs scene.hlsli; miss shader 1 is the shadow miss.
#include "common/emission.h"
#include "common/bsdf.h"
#include "direct_lighting/payloads.hlsli"

struct LightSample { float3 toLight; float distance; float3 irradiance; };

LightSample sampleLight(GpuLight light, float3 p) {
    LightSample s;
    if (light.type == kLightDirectional) {
        s.toLight = -light.direction;
        s.distance = 1.0e6f;
        s.irradiance = light.intensity;
        return s;
    }
    float3 v = light.position - p;
    float d2 = max(dot(v, v), 1.0e-8f);
    s.distance = sqrt(d2);
    s.toLight = v / s.distance;
    float falloff = 1.0f / d2;
    if (light.range > 0.0f) {
        float r = s.distance / light.range;
        float w = saturate(1.0f - r * r * r * r);
        falloff *= w * w;
    }
    if (light.type == kLightSpot) falloff *= spotAttenuation(dot(-s.toLight, light.direction), light.cosInner, light.cosOuter);
    s.irradiance = light.intensity * falloff;
    return s;
}

float shadowVisibility(float3 p, float3 n, float3 toLight, float distance) {
    float eps = 1.0e-4f * (1.0f + max(max(abs(p.x), abs(p.y)), abs(p.z)));
    RayDesc ray;
    ray.Origin = p + n * eps;
    ray.TMin = 0.0f;
    ray.Direction = toLight;
    ray.TMax = max(distance - 2.0f * eps, 0.0f);
    ShadowPayload shadow;
    shadow.unoccluded = 0u;
    TraceRay(sceneTlas, RAY_FLAG_ACCEPT_FIRST_HIT_AND_END_SEARCH | RAY_FLAG_FORCE_OPAQUE | RAY_FLAG_SKIP_CLOSEST_HIT_SHADER,
             0xFF, 0, 1, 1, ray, shadow);
    return float(shadow.unoccluded);
}

// Sum of f_r(l, v) E_l cos(theta_l) V_l with the one glTF BRDF of shaders/common/bsdf.h.
float3 shadeDirect(float3 p, float3 n, float3 v, BrdfMaterial brdf) {
    float3 result = (float3)0.0f;
    uint count = sceneLightCount();
    for (uint i = 0u; i < count; ++i) {
        LightSample s = sampleLight(sceneLight(i), p);
        float nl = dot(n, s.toLight);
        if (nl <= 0.0f || max(s.irradiance.r, max(s.irradiance.g, s.irradiance.b)) <= 0.0f) continue;
        float3 f = evalGltfBrdf(brdf, n, s.toLight, v);
        if (max(f.r, max(f.g, f.b)) <= 0.0f) continue;
        result += f * s.irradiance * (nl * shadowVisibility(p, n, s.toLight, s.distance));
    }
    return result;
}
#endif
