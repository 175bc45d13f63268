#ifndef CAUSTICS_COMMON_SPECULAR_EVENT_H
#define CAUSTICS_COMMON_SPECULAR_EVENT_H
// One scattering event at a specular surface, used by the forward (photon) and backward (camera)
// tracers alike. Lobes follow glTF 2.0 metallic-roughness + KHR_materials_transmission/ior:
//   metal      (probability metallic):      reflect, weight Schlick(F0 = baseColor)
//   dielectric (probability 1 - metallic):  reflect with probability F (exact Fresnel), weight 1;
//                                           else refract with probability transmission, weight
//                                           baseColor; else the diffuse base layer (kind Diffuse:
//                                           the caller ends the specular chain there; weight 1 for
//                                           photons, 1 / its chance for camera paths, below).
//   thin wall (KHR_materials_volume absent): as a dielectric with F the pane's 2R/(1+R), both faces
//                                           and their inner reflections summed; it does not bend.
// Each lobe is picked with its physical probability, so Fresnel cancels out of the weights
// (importance sampling). Rough surfaces sample a GGX microfacet normal first (Walter et al. 2007).
#include "common/fresnel.h"
#include "common/lang.h"
#include "common/microfacet.h"
#include "common/sampling.h"

CAUSTICS_SHARED_BEGIN

CAUSTICS_CONST uint kEventAbsorbed = 0u;
CAUSTICS_CONST uint kEventReflect = 1u;
CAUSTICS_CONST uint kEventRefract = 2u;
CAUSTICS_CONST uint kEventDiffuse = 3u;

// Photons carry flux (importance transport: no eta^2 factor, flux is conserved across an interface);
// camera paths carry radiance, which scales by (etaI/etaT)^2 on refraction (Veach 1997, sec. 5.2;
// PBRT 3e sec. 16.1.3).
CAUSTICS_CONST uint kTransportImportance = 0u;
CAUSTICS_CONST uint kTransportRadiance = 1u;

struct OpticalMaterial {
    float3 baseColor;
    float metallic;
    float roughness;
    float transmission;
    float ior;
    bool thinWalled;  // KHR_materials_volume absent (thickness 0): transmission does not bend
};

struct SpecularEvent {
    float3 direction;  // new unit propagation direction
    float3 weight;     // multiply the path throughput by this
    uint kind;         // kEvent*
    bool insideMedium; // the new segment runs inside the object's volume
    // The lobe taken is the most probable of the four (metal, dielectric reflection, refraction, diffuse
    // base): a camera path that took only such lobes gives the second type's filter guides
    // (docs/caustics.md "Second-type guides").
    bool mostLikely;
};

// The surface side and microfacet an event sees: d, n as for sampleSpecularEvent, u the two numbers
// that pick the microfacet normal on a rough surface.
struct SpecularFacet {
    bool entering;
    float3 nf;      // the normal facing the incoming ray
    float etaI;
    float etaT;
    float alpha;    // GGX alpha
    float3 m;       // the microfacet normal (nf where smooth)
    float cosOm;    // <= 0: a back-facing microfacet, no event
    float f;        // the dielectric's reflectance at m
};

CAUSTICS_FN SpecularFacet specularFacet(float3 d, float3 n, OpticalMaterial mat, float2 u) {
    SpecularFacet s;
    s.entering = dot(d, n) < 0.0f;
    s.nf = s.entering ? n : -n;
    s.etaI = s.entering ? 1.0f : mat.ior;
    s.etaT = s.entering ? mat.ior : 1.0f;
    if (mat.thinWalled) {
        s.etaI = 1.0f;
        s.etaT = mat.ior;
    }
    s.alpha = ggxAlpha(mat.roughness);
    s.m = s.nf;
    if (s.alpha > kSmoothAlpha) {
        s.m = onbToWorld(onbFromNormal(s.nf), ggxSampleNormal(u, s.alpha));
    }
    s.cosOm = dot(-d, s.m);
    // A thin wall reflects as a pane with both faces' inner reflections summed (common/fresnel.h).
    s.f = mat.thinWalled ? thinPaneReflectance(s.cosOm, mat.ior) : fresnelDielectric(s.cosOm, s.etaT / s.etaI);
    return s;
}

// The probabilities sampleSpecularEvent picks its lobes with, for the microfacet of u.xy, in the order
// their intervals of u.z follow each other: metal, dielectric reflection, refraction, diffuse base.
// All zero on a back-facing microfacet.
struct SpecularLobeChances {
    float metal;
    float reflect;
    float refract;
    float diffuse;
};

CAUSTICS_FN SpecularLobeChances specularLobeChancesAt(SpecularFacet s, OpticalMaterial mat) {
    SpecularLobeChances c;
    float dielectric = s.cosOm > 0.0f ? 1.0f - mat.metallic : 0.0f;
    c.metal = s.cosOm > 0.0f ? mat.metallic : 0.0f;
    c.reflect = dielectric * s.f;
    c.refract = dielectric * (1.0f - s.f) * mat.transmission;
    c.diffuse = dielectric * (1.0f - s.f) * (1.0f - mat.transmission);
    return c;
}

// Lobe `lobe`'s interval of the u.z that sampleSpecularEvent picks lobes with (0 metal, 1 reflection,
// 2 refraction, 3 diffuse; SpecularLobeChances order): its start and its width, the lobe's chance.
CAUSTICS_FN float2 specularLobeInterval(SpecularLobeChances c, uint lobe) {
    float start = 0.0f;
    if (lobe > 0u) start += c.metal;
    if (lobe > 1u) start += c.reflect;
    if (lobe > 2u) start += c.refract;
    float width = lobe == 0u ? c.metal : (lobe == 1u ? c.reflect : (lobe == 2u ? c.refract : c.diffuse));
    return float2(start, width);
}

// The u.z that picks lobe `lobe`: the middle of its interval.
CAUSTICS_FN float specularLobePickCentre(SpecularLobeChances c, uint lobe) {
    float2 i = specularLobeInterval(c, lobe);
    return i.x + 0.5f * i.y;
}

// The u.z that picks among the lobes other than `lobe` in proportion to their chances, for u uniform in
// [0, 1 - chance of `lobe`): u with `lobe`'s interval cut out.
CAUSTICS_FN float specularLobePickOutside(SpecularLobeChances c, uint lobe, float u) {
    float2 i = specularLobeInterval(c, lobe);
    return min(u < i.x ? u : u + i.y, 0.99999994f);
}

// The most probable lobe (SpecularLobeChances order; the first of equals).
CAUSTICS_FN uint specularMostLikelyLobe(SpecularLobeChances c) {
    uint most = 0u;
    float p = c.metal;
    if (c.reflect > p) { most = 1u; p = c.reflect; }
    if (c.refract > p) { most = 2u; p = c.refract; }
    if (c.diffuse > p) most = 3u;
    return most;
}

// sampleSpecularEvent on the facet s (specularFacet of d, n, mat and the u.xy it was given), with pick
// the u.z that picks the lobe: a caller that looked at the facet's lobe chances first does not
// compute the facet twice.
CAUSTICS_FN SpecularEvent sampleSpecularEventOnFacet(SpecularFacet s, float3 d, OpticalMaterial mat, float pick, uint transportMode) {
    SpecularEvent ev;
    ev.direction = d;
    ev.weight = splat3(0.0f);
    ev.kind = kEventAbsorbed;
    ev.insideMedium = false;
    ev.mostLikely = false;
    if (s.cosOm <= 0.0f) return ev;  // back-facing microfacet: zero contribution (Walter eq. 41)
    float3 wo = -d;
    float cosOn = dot(wo, s.nf);
    float cosMn = dot(s.m, s.nf);

    SpecularLobeChances chances = specularLobeChancesAt(s, mat);
    float pReflect = chances.reflect, pRefract = chances.refract, pDiffuse = chances.diffuse;
    float pMost = max(max(mat.metallic, pReflect), max(pRefract, pDiffuse));
    float3 lobeWeight = splat3(1.0f);
    bool doReflect = false;
    if (pick < mat.metallic) {
        doReflect = true;
        lobeWeight = fresnelSchlick(mat.baseColor, s.cosOm);
        ev.mostLikely = mat.metallic >= pMost;
    } else {
        pick = (pick - mat.metallic) / max(1.0f - mat.metallic, 1.0e-7f);
        if (pick < s.f) {
            doReflect = true;
            ev.mostLikely = pReflect >= pMost;
        } else {
            pick = (pick - s.f) / max(1.0f - s.f, 1.0e-7f);
            if (pick >= mat.transmission) {
                // The diffuse base. A photon leaves its flux there (weight unused); the photons that
                // picked the base carry its chance already, so a camera path that picks it shows that
                // photon radiance at weight 1 / chance: as the first type shows the base seen directly
                // (docs/physics.md "A diffuse base behind glass").
                ev.kind = kEventDiffuse;
                ev.weight = splat3(transportMode == kTransportRadiance ? 1.0f / max(pDiffuse, 1.0e-7f) : 1.0f);
                ev.insideMedium = !s.entering && !mat.thinWalled;
                ev.mostLikely = pDiffuse >= pMost;
                return ev;
            }
            ev.mostLikely = pRefract >= pMost;
        }
    }

    float3 wi;
    if (doReflect) {
        wi = reflect(d, s.m);
        if (dot(wi, s.nf) <= 0.0f) return ev;
        ev.kind = kEventReflect;
        ev.insideMedium = !s.entering && !mat.thinWalled;
    } else if (mat.thinWalled) {
        // A thin wall is two parallel interfaces: the ray leaves along its incident direction.
        wi = d;
        ev.kind = kEventRefract;
        ev.insideMedium = false;
        lobeWeight = mat.baseColor;
    } else {
        if (!refractDirection(d, s.m, s.etaI / s.etaT, wi)) return ev;  // cannot happen: F = 1 under TIR
        if (dot(wi, s.nf) >= 0.0f) return ev;
        ev.kind = kEventRefract;
        ev.insideMedium = s.entering;
        lobeWeight = mat.baseColor;
        if (transportMode == kTransportRadiance) lobeWeight = lobeWeight * ((s.etaI * s.etaI) / (s.etaT * s.etaT));
    }
    float micro = 1.0f;
    if (s.alpha > kSmoothAlpha) micro = ggxSampleWeight(cosOn, dot(wi, s.nf), s.cosOm, dot(wi, s.m), cosMn, s.alpha);
    ev.direction = wi;
    ev.weight = lobeWeight * micro;
    return ev;
}

// d: unit propagation direction arriving at the surface; n: the surface's outward unit normal (the
// side of the volume it bounds). dot(d, n) < 0 means the ray enters, > 0 that it leaves.
// u: three uniform numbers in [0, 1): u.xy pick the microfacet, u.z the lobe.
CAUSTICS_FN SpecularEvent sampleSpecularEvent(float3 d, float3 n, OpticalMaterial mat, float3 u, uint transportMode) {
    return sampleSpecularEventOnFacet(specularFacet(d, n, mat, float2(u.x, u.y)), d, mat, u.z, transportMode);
}

CAUSTICS_SHARED_END

#endif  // CAUSTICS_COMMON_SPECULAR_EVENT_H
