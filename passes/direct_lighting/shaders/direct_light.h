#ifndef CAUSTICS_PASS_DIRECT_LIGHT_H
#define CAUSTICS_PASS_DIRECT_LIGHT_H
// The light a KHR_lights_punctual light brings to a point, and the payloads of direct_lighting's
// state object, in the shared dialect (docs/shaders.md). Hit group 0 ("surfaceHit") reports which
// triangle a surface ray hit (the ray-generation shader rebuilds the surface with sceneSurfaceHit);
// miss 0 ("surfaceMiss") leaves instance = ~0; miss 1 ("shadowMiss") marks a shadow ray unoccluded.
#include "common/emission.h"
#include "common/scene.h"

CAUSTICS_SHARED_BEGIN
struct SurfacePayload {
    uint instance;   // ~0u: missed
    uint primitive;
    float2 barycentrics;
};
struct ShadowPayload {   // a struct: DXR payloads must be
    uint unoccluded;
};

// Light arriving at p: direction towards the light, distance, and the irradiance on a surface
// facing the light (lux). KHR_lights_punctual: point/spot E = I / d^2 (candela -> lux) with the
// recommended range window saturate(1 - (d/range)^4)^2 and the smooth spot cone; directional E = lux.
struct LightSample {
    float3 toLight;
    float distance;
    float3 irradiance;
};

CAUSTICS_FN LightSample sampleLight(GpuLight light, float3 p) {
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

// Offset of a continuing ray from p: relative to the coordinates' magnitude (float spacing).
CAUSTICS_FN float surfaceOffset(float3 p) { return 1.0e-4f * (1.0f + max(max(abs(p.x), abs(p.y)), abs(p.z))); }
CAUSTICS_SHARED_END

#endif  // CAUSTICS_PASS_DIRECT_LIGHT_H
