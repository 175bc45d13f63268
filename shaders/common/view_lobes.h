#ifndef CAUSTICS_COMMON_VIEW_LOBES_H
#define CAUSTICS_COMMON_VIEW_LOBES_H
// The lobes a camera path follows at a smooth specular surface when direct lighting looks through
// glass and into mirrors (the paper's section 3.1 "transparencies and reflections"; docs/caustics.md
// "Direct light through glass"). Unlike common/specular_event.h, which picks one lobe at random for
// photons, both lobes are returned with their weights, so the caller can follow both (a split) and
// glass shows its Fresnel reflection as well as what lies behind it:
//   metal (metallic > 0.5): reflection, weight Schlick(F0 = baseColor, cos i);
//   dielectric: reflection, weight F (exact Fresnel), and refraction, weight
//               transmission (1 - F) baseColor (none under total internal reflection);
//   thin wall:  the same with F the pane's 2R/(1+R) (both faces, inner reflections summed), unbent.
// The (etaI/etaT)^2 radiance scaling of refraction is left out: a camera path that enters a closed
// object also leaves it, and the two factors cancel.
#include "common/fresnel.h"
#include "common/lang.h"

CAUSTICS_SHARED_BEGIN

struct ViewLobes {
    float3 reflectDirection;
    float3 reflectWeight;
    float3 refractDirection;
    float3 refractWeight;  // zero: no refracted lobe
};

// d: unit propagation direction; n: unit shading normal facing the incoming path (dot(d, n) < 0);
// entering: whether d enters the object's volume here (ignored for thin walls, which do not bend).
CAUSTICS_FN ViewLobes specularViewLobes(float3 d, float3 n, float3 baseColor, float metallic, float transmission,
                                        float ior, bool thinWalled, bool entering) {
    ViewLobes l;
    float cosI = max(dot(-d, n), 0.0f);
    l.reflectDirection = normalize(reflect(d, n));
    l.refractDirection = d;
    l.refractWeight = splat3(0.0f);
    if (metallic > 0.5f) {
        l.reflectWeight = fresnelSchlick(baseColor, cosI);
        return l;
    }
    float eta = thinWalled ? 1.0f : (entering ? ior : 1.0f / ior);
    float fr = thinWalled ? thinPaneReflectance(cosI, ior) : fresnelDielectric(cosI, eta);
    l.reflectWeight = splat3(fr);
    float3 t;
    if (thinWalled) {
        l.refractWeight = baseColor * (transmission * (1.0f - fr));
    } else if (refractDirection(d, n, 1.0f / eta, t)) {
        l.refractDirection = t;
        l.refractWeight = baseColor * (transmission * (1.0f - fr));
    }
    return l;
}

CAUSTICS_FN float maxComponent(float3 v) { return max(v.x, max(v.y, v.z)); }

CAUSTICS_SHARED_END

#endif  // CAUSTICS_COMMON_VIEW_LOBES_H
