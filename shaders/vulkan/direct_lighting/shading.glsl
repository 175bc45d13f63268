#ifndef CAUSTICS_DIRECT_SHADING_GLSL
#define CAUSTICS_DIRECT_SHADING_GLSL
// Direct illumination from KHR_lights_punctual lights with ray-traced shadows. Needs scene.glsl and
// a `rayPayloadEXT uint shadowUnoccluded` at location 1, miss shader index 1 = shadow miss.
#include "common/emission.h"
#include "common/bsdf.h"

// Light arriving at p: direction towards the light, distance, and the irradiance on a surface
// facing the light (lux). KHR_lights_punctual: point/spot E = I / d^2 (candela -> lux) with the
// recommended range window saturate(1 - (d/range)^4)^2 and the smooth spot cone; directional E = lux.
struct LightSample { vec3 toLight; float distance; vec3 irradiance; };

LightSample sampleLight(GpuLight light, vec3 p) {
    LightSample s;
    if (light.type == kLightDirectional) {
        s.toLight = -light.direction;
        s.distance = 1.0e6;
        s.irradiance = light.intensity;
        return s;
    }
    vec3 v = light.position - p;
    float d2 = max(dot(v, v), 1.0e-8);
    s.distance = sqrt(d2);
    s.toLight = v / s.distance;
    float falloff = 1.0 / d2;
    if (light.range > 0.0) {
        float r = s.distance / light.range;
        float w = saturate(1.0 - r * r * r * r);
        falloff *= w * w;
    }
    if (light.type == kLightSpot) falloff *= spotAttenuation(dot(-s.toLight, light.direction), light.cosInner, light.cosOuter);
    s.irradiance = light.intensity * falloff;
    return s;
}

layout(location = 1) rayPayloadEXT uint shadowUnoccluded;

// 1 when nothing (diffuse or specular: light through glass is the caustic passes' job) lies between
// p and the light.
float shadowVisibility(vec3 p, vec3 n, vec3 toLight, float distance) {
    // Offset along the normal scaled with the distance from the origin (float precision of p).
    float eps = 1.0e-4 * (1.0 + max(max(abs(p.x), abs(p.y)), abs(p.z)));
    vec3 origin = p + n * eps;
    shadowUnoccluded = 0u;
    traceRayEXT(sceneTlas, gl_RayFlagsTerminateOnFirstHitEXT | gl_RayFlagsOpaqueEXT | gl_RayFlagsSkipClosestHitShaderEXT,
                0xFF, 0, 1, 1, origin, 0.0, toLight, max(distance - 2.0 * eps, 0.0), 1);
    return float(shadowUnoccluded);
}

// Outgoing radiance towards v of a surface point lit by every scene light: sum of
// f_r(l, v) E_l cos(theta_l) V_l with the one glTF BRDF of shaders/common/bsdf.h (docs/physics.md,
// "One BSDF"), the same one the caustic splat and gather evaluate.
vec3 shadeDirect(vec3 p, vec3 n, vec3 v, BrdfMaterial brdf) {
    vec3 result = vec3(0.0);
    for (uint i = 0u; i < sceneLightCount; ++i) {
        LightSample s = sampleLight(sceneLights[i], p);
        float nl = dot(n, s.toLight);
        if (nl <= 0.0 || max(s.irradiance.r, max(s.irradiance.g, s.irradiance.b)) <= 0.0) continue;
        vec3 f = evalGltfBrdf(brdf, n, s.toLight, v);
        if (max(f.r, max(f.g, f.b)) <= 0.0) continue;
        result += f * s.irradiance * (nl * shadowVisibility(p, n, s.toLight, s.distance));
    }
    return result;
}

#endif
