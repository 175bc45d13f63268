#ifndef CAUSTICS_COMMON_BSDF_H
#define CAUSTICS_COMMON_BSDF_H
// The one reflectance model of a diffuse receiver (docs/physics.md, "One BSDF"): the glTF 2.0
// metallic-roughness BRDF of the spec's Appendix B, with KHR_materials_transmission's base mix,
//   f = (1 - metallic)(1 - transmission)(1 - F_d) baseColor / pi          (Lambert, "fresnel_mix")
//     + F(F0 = mix(dielectricF0, baseColor, metallic), |wo.h|) D(h) G(wi, wo) / (4 |n.wi| |n.wo|)
// with Schlick's F (F_d: Schlick with the scalar dielectricF0) and GGX D and separable Smith G
// (common/microfacet.h). Direct lighting, the first-type splat, the second-type gather and the CPU
// reference all evaluate it, so one receiver reflects light through one BRDF whichever way the light
// arrived (before, the splat used Lambert alone while direct lighting added the GGX lobe).
// Units: f_r in 1/sr. wi points from the surface towards where the light came from (the light, or
// back along the photon's last segment); wo towards the viewer; n is the shading normal on the
// lit side. Reflection only: f = 0 when wi or wo is below the surface.
#include "common/fresnel.h"
#include "common/lang.h"
#include "common/microfacet.h"

CAUSTICS_SHARED_BEGIN

// Point lights have no area: a perfectly smooth receiver would show them as an invisible delta, so
// the specular lobe is evaluated with at least this roughness (the highlight stays visible).
CAUSTICS_CONST float kMinReceiverRoughness = 0.05f;
// glTF 2.0 core: a dielectric's normal-incidence reflectance, IOR 1.5 and specular 1.
CAUSTICS_CONST float kGltfDielectricF0 = 0.04f;

struct BrdfMaterial {
    float3 baseColor;     // linear
    float metallic;
    float roughness;      // perceptual, alpha = roughness^2
    float transmission;   // KHR_materials_transmission factor: removes the diffuse base
    float dielectricF0;   // specular x ((ior - 1) / (ior + 1))^2 (KHR_materials_ior/specular)
};

CAUSTICS_FN BrdfMaterial makeBrdfMaterial(float3 baseColor, float metallic, float roughness, float transmission,
                                          float dielectricF0) {
    BrdfMaterial m;
    m.baseColor = baseColor;
    m.metallic = metallic;
    m.roughness = roughness;
    m.transmission = transmission;
    m.dielectricF0 = dielectricF0;
    return m;
}

// The diffuse base alone (f = baseColor / pi): a specular material's diffuse layer, reached by a
// sampled event that already carried the layer's Fresnel/metallic/transmission weights.
CAUSTICS_FN BrdfMaterial lambertOnlyBrdfMaterial(float3 baseColor) {
    return makeBrdfMaterial(baseColor, 0.0f, 1.0f, 0.0f, 0.0f);
}

// KHR_materials_ior + KHR_materials_specular: the dielectric layer's normal-incidence reflectance.
CAUSTICS_FN float gltfDielectricF0(float specular, float ior) { return specular * dielectricF0(ior); }

// f_r(wi, wo) in 1/sr, the formula at the top of this file.
// The diffuse term's weight (the first line of the formula above, without baseColor) at |wo.h| = vh.
CAUSTICS_FN float gltfDiffuseWeight(BrdfMaterial m, float vh) {
    float fresnelDiffuse = m.dielectricF0 > 0.0f ? fresnelSchlick(splat3(m.dielectricF0), vh).x : 0.0f;
    return (1.0f - m.metallic) * (1.0f - m.transmission) * (1.0f - fresnelDiffuse) * kInvPi;
}

// The diffuse term alone: a specular material's diffuse base lit directly where a view reaches it
// through glass or in a mirror (passes/direct_lighting; its GGX highlight, a one-pixel spike at
// specular roughness, is left out there). f_r in 1/sr.
CAUSTICS_FN float3 evalGltfDiffuse(BrdfMaterial m, float3 n, float3 wi, float3 wo) {
    if (dot(n, wi) <= 0.0f || dot(n, wo) <= 0.0f) return splat3(0.0f);
    return m.baseColor * gltfDiffuseWeight(m, saturate(dot(wo, normalize(wi + wo))));
}

CAUSTICS_FN float3 evalGltfBrdf(BrdfMaterial m, float3 n, float3 wi, float3 wo) {
    float nl = dot(n, wi);
    float nv = dot(n, wo);
    if (nl <= 0.0f || nv <= 0.0f) return splat3(0.0f);
    float3 h = normalize(wi + wo);
    float vh = saturate(dot(wo, h));
    float alpha = ggxAlpha(max(m.roughness, kMinReceiverRoughness));
    float g = ggxSmithG1(nv, vh, alpha) * ggxSmithG1(nl, dot(wi, h), alpha);
    float specular = ggxD(dot(n, h), alpha) * g / (4.0f * nl * nv);
    float3 f0 = lerp(splat3(m.dielectricF0), m.baseColor, m.metallic);
    // F0 = 0 is an index-matched interface: no specular layer at all (Schlick's grazing term would
    // otherwise invent one). The forward trace uses it for the diffuse base of a specular material,
    // whose layer weights were already applied when the event picked that lobe.
    if (max(f0.x, max(f0.y, f0.z)) <= 0.0f) return m.baseColor * ((1.0f - m.transmission) * kInvPi);
    return m.baseColor * gltfDiffuseWeight(m, vh) + fresnelSchlick(f0, vh) * specular;
}

// The receiver BRDF of a glTF core material (IOR 1.5, specular 1, no transmission): what a caustic
// receiver that carries only base colour, metallic and roughness reflects. f_r in 1/sr.
CAUSTICS_FN float3 receiverBrdf(float3 baseColor, float metallic, float roughness, float3 n, float3 wi, float3 wo) {
    return evalGltfBrdf(makeBrdfMaterial(baseColor, metallic, roughness, 0.0f, kGltfDielectricF0), n, wi, wo);
}

CAUSTICS_SHARED_END

#endif  // CAUSTICS_COMMON_BSDF_H
