#version 460
#extension GL_GOOGLE_include_directive : require
// Compiles every shared header as GLSL (CTest: Glsl.CommonHeadersCompile). Calls each entry point
// once so that glslang type-checks the calls as well as the definitions.
#include "common/lang.h"
#include "common/rng.h"
#include "common/sampling.h"
#include "common/fresnel.h"
#include "common/microfacet.h"
#include "common/volume.h"
#include "common/specular_event.h"
#include "common/camera.h"
#include "common/emission.h"
#include "common/bsdf.h"
#include "common/ray_differential.h"
#include "common/gather_disk.h"
#include "common/caster_motion.h"

layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Out { float4 values[]; };

void main() {
    uint id = gl_GlobalInvocationID.x;
    Rng rng = rngCreate(id, 1u, 2u, 3u);
    float3 u = rngNextFloat3(rng);
    Onb onb = onbFromNormal(normalize(float3(0.3f, -0.5f, 0.8f)));
    float3 dir = onbToWorld(onb, sampleCosineHemisphere(float2(u.x, u.y)));
    dir += sampleUniformSphere(rngNextFloat2(rng)) + sampleUniformCone(float2(u.y, u.z), 0.9f);
    OpticalMaterial mat;
    mat.baseColor = splat3(1.0f);
    mat.metallic = 0.0f;
    mat.roughness = 0.1f;
    mat.transmission = 1.0f;
    mat.ior = 1.5f;
    mat.thinWalled = false;
    SpecularEvent ev = sampleSpecularEvent(normalize(dir), onb.n, mat, u, kTransportImportance);
    float3 t;
    bool ok = refractDirection(float3(0.0f, 0.0f, -1.0f), float3(0.0f, 0.0f, 1.0f), 1.0f / 1.5f, t);
    float f = fresnelDielectric(u.x, 1.5f) + fresnelSchlick(splat3(0.9f), u.y).x + dielectricF0(1.5f);
    float3 absorb = beerLambert(volumeSigmaA(float3(0.5f, 0.6f, 0.7f), 2.0f), 1.0f);
    PinholeCamera cam = makePinholeCamera(splat3(0.0f), float3(0.0f, 0.0f, -1.0f), float3(0.0f, 1.0f, 0.0f), 0.8f, 64.0f, 64.0f);
    CameraProjection proj = projectToCamera(cam, ev.direction);
    float w = pinholeSplatFactor(cam, proj.cosTheta, 0.5f, proj.distance) + pinholeImportance(cam, 0.9f);
    float e = photonFluxPerspective(10.0f, perspectiveTexelSolidAngle(uint2(id, 0u), 512.0f, 1.0f), 1.0f) +
              photonFluxOrthographic(5.0f, orthographicTexelArea(2.0f, 512.0f), 2.0f) +
              spotAttenuation(0.9f, 0.95f, 0.8f) + spotLightFlux(1.0f, 0.95f, 0.8f) + perspectiveFrustumSolidAngle(1.0f);
    float3 c = cameraRayDirection(cam, proj.pixel) + absorb + lerp(t, ev.weight, 0.5f) + saturate(dir);
    BrdfMaterial brdf = makeBrdfMaterial(splat3(0.5f), u.x, u.y, 0.0f, gltfDielectricF0(1.0f, 1.5f));
    c += evalGltfBrdf(brdf, onb.n, dir, normalize(float3(0.0f, 0.2f, 1.0f))) +
         evalGltfBrdf(lambertOnlyBrdfMaterial(splat3(1.0f)), onb.n, onb.n, onb.n) + receiverBrdf(c, 0.0f, 1.0f, onb.n, onb.n, onb.n);
    RayDifferential rd = pinholeRayDifferential(cam, proj.pixel);
    rd = transferRayDifferential(rd, dir, 1.0f, onb.n);
    float3 dN = shadingNormalDerivative(float3(1.0f, 0.0f, 0.0f), float3(0.0f, 0.0f, 1.0f), u, dir, onb.n, rd.dPdx);
    rd = scatterRayDifferential(reflectRayDifferential(rd, dir, onb.n, dN, dN), dir, ev, onb.n, dN, dN, mat);
    rd = refractRayDifferential(rd, dir, t, onb.n, 0.7f, dN, dN);
    GatherRadiusLimits limits;
    limits.scale = 2.0f;
    limits.minMagnification = 0.1f;
    limits.maxMagnification = 10.0f;
    limits.minRadius = 1e-4f;
    limits.maxRadius = 1.0f;
    float g = gatherDiskRadius(rayFootprintArea(rd), rayFootprintMajorAxis(rd), 0.01f, limits) + (insideGatherDisk(dir, t, onb.n, 0.5f) ? 1.0f : 0.0f);
    values[id] = float4(c, f + w + e + g + (ok ? 1.0f : 0.0f) + ggxD(0.9f, 0.1f));
}
