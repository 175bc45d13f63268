// Forward caustic trace (paper 3.2, Figure 4; mirror of shaders/vulkan/forward_trace/forward_body.glsl):
// one launch per (emitting map texel, sample) of the caustics.emitters list. Shared by forward.rgen.hlsl
// and forward_fixed.rgen.hlsl.
#include "scene/scene.hlsli"
#include "scene/camera.hlsli"
#include "common/emission.h"
#include "common/rng.h"
#include "common/volume.h"
#include "caustic_maps/caustic_map.hlsli"
#include "caustic_maps/emitter_list.hlsli"
#include "caustic_maps/layer_plan.hlsli"
#include "forward_trace/caustic_hit.hlsli"

struct CameraBlock { CameraConstants camera; };
ConstantBuffer<CameraBlock> cameraBlock : register(b0, space1);
ByteAddressBuffer maps : register(t1, space1);
ByteAddressBuffer emitters : register(t2, space1);
Texture2D<float4> gLinearDepth : register(t3, space1);
Texture2D<uint> gObjectId : register(t4, space1);
RWByteAddressBuffer hits : register(u6, space1);
RWByteAddressBuffer stats : register(u7, space1);
RWByteAddressBuffer plans : register(u8, space1);
ByteAddressBuffer owners : register(t9, space1);
#define RADIANCE_REGISTER u5
#define RADIANCE_SPACE space1
#include "forward_trace/radiance_atomics.hlsli"

struct Push {
    uint mapSize;
    uint layers;
    uint instanceCount;   // row length of owners
    uint maxDepth;
    uint frame;
    uint flags;   // bit 0: Russian roulette
    uint maxStoredHits;
    uint pad;
};
ConstantBuffer<Push> pc : register(b0, space999);

void statAdd(uint slot, uint value, out uint original) { stats.InterlockedAdd(4u * slot, value, original); }
void statAdd(uint slot, uint value) { stats.InterlockedAdd(4u * slot, value); }

// The receiver's BRDF (shaders/common/bsdf.h). A specular material reaches here only through its
// diffuse layer, whose Fresnel/metallic/transmission weights the sampled event already applied.
BrdfMaterial receiverBrdfMaterial(SurfaceHit h) {
    GpuMaterial m = h.material;
    if (sceneMaterialIsSpecular(m)) return lambertOnlyBrdfMaterial(h.baseColor);
    return makeBrdfMaterial(h.baseColor, m.metallic, m.roughness, m.transmission, gltfDielectricF0(m.specular, m.ior));
}

void splatFirstType(CameraConstants camera, float3 x, float3 nFacing, uint objectId, float3 flux, float3 incoming,
                    BrdfMaterial brdf) {
    PinholeCamera cam = cameraPinhole(camera);
    CameraProjection pr = cameraProject(camera, x);
    if (!pr.valid || pr.depth < camera.clip.x) return;
    float3 toEye = (cam.eye - x) / pr.distance;
    float cosSurface = dot(nFacing, toEye);
    if (cosSurface <= 0.0f) return;
    int2 px = int2(pr.pixel);
    if (gObjectId.Load(int3(px, 0)) != objectId) return;
    float gDepth = gLinearDepth.Load(int3(px, 0)).r;
    float footprint = 2.0f * cam.tanHalfFovY / cam.height;
    float tanView = min(sqrt(max(0.0f, 1.0f - cosSurface * cosSurface)) / cosSurface, 20.0f);
    if (abs(pr.depth - gDepth) > gDepth * (1e-3f + 1.5f * footprint * tanView)) return;
    float factor = pinholeSplatFactor(cam, pr.cosTheta, cosSurface, pr.distance);
    // The material as the stored hit holds it (metallic and roughness unorm16-packed), as the Vulkan
    // splat evaluates it (causticHitReflectedFlux): both APIs splat the same radiance.
    float2 mr = unpackUnorm2x16(packUnorm2x16(float2(brdf.metallic, brdf.roughness)));
    BrdfMaterial stored = makeBrdfMaterial(brdf.baseColor, mr.x, mr.y, brdf.transmission, brdf.dielectricF0);
    float3 reflected = flux * evalGltfBrdf(stored, nFacing, incoming, toEye);
    addRadiance(uint(px.y) * camera.frame.x + uint(px.x), reflected * factor);
    statAdd(kStatSplats, 1u);
}

[shader("raygeneration")]
void main() {
    CameraConstants camera = cameraBlock.camera;
    uint launch = DispatchRaysIndex().x;
    if (launch == 0u) statAdd(kStatDispatchedTexels, DispatchRaysDimensions().x);
    int layer = -1;
    for (uint k = 0u; k < pc.layers && layer < 0; ++k)
        if (launch - plans.Load(layerPlanAddress(k, kLayerPlanLaunchOffset)) < plans.Load(layerPlanAddress(k, kLayerPlanLaunches)))
            layer = int(k);
    if (layer < 0) return;
    uint local = launch - plans.Load(layerPlanAddress(uint(layer), kLayerPlanLaunchOffset));
    uint emitterCount = plans.Load(layerPlanAddress(uint(layer), kLayerPlanEmitters));
    uint packed = emitters.Load(4u * (uint(layer) * pc.mapSize * pc.mapSize + local % emitterCount));
    uint tx = emitterTexel(packed).x;
    uint ty = emitterTexel(packed).y;
    uint sampleIndex = local / emitterCount;
    float raysPerTexel = asfloat(plans.Load(layerPlanAddress(uint(layer), kLayerPlanRaysPerTexel)));
    CausticMap m = loadCausticMap(maps, uint(layer));

    Rng rng = rngCreate(ty * pc.mapSize + tx, m.light | (m.cluster << 6), sampleIndex, pc.frame);
    float emitProbability = clamp(raysPerTexel - float(sampleIndex), 0.0f, 1.0f);
    if (emitProbability < 1.0f && rngNextFloat(rng) >= emitProbability) return;
    statAdd(kStatRaysPerLight + m.light, 1u);
    plans.InterlockedAdd(layerPlanAddress(uint(layer), kLayerPlanEmitted), 1u);

    float2 coord = float2(tx, ty) + rngNextFloat2(rng);
    float n = float(pc.mapSize);
    float3 origin, dir, flux;
    if (m.orthographic != 0u) {
        float2 q = m.extent * (2.0f * coord / n - 1.0f);
        origin = m.origin + q.x * m.right + q.y * m.up;
        dir = m.forward;
        flux = m.intensity * photonFluxOrthographic(1.0f, orthographicTexelArea(m.extent, n), raysPerTexel);
    } else {
        float2 q = perspectiveMapPlanePoint(coord, n, m.extent);
        origin = m.origin;
        dir = normalize(m.forward + q.x * m.right + q.y * m.up);
        float omega = perspectiveTexelSolidAngle(uint2(tx, ty), n, m.extent);
        float falloff = m.cosOuter > -1.0f ? spotAttenuation(dot(dir, m.spotAxis), m.cosInner, m.cosOuter) : 1.0f;
        flux = m.intensity * (falloff * photonFluxPerspective(1.0f, omega, raysPerTexel));
    }
    if (max(flux.x, max(flux.y, flux.z)) <= 0.0f) return;

    float3 sigma = (float3)0.0f;
    float3 throughput = (float3)1.0f;
    uint events = 0u;
    uint segments = 0u;
    for (uint vertex = 0u; vertex <= pc.maxDepth + 1u; ++vertex) {
        TracePayload payload;
        payload.barycentrics = (float2)0.0f;
        payload.instance = 0u;
        payload.primitive = 0u;
        payload.t = -1.0f;
        RayDesc ray;
        ray.Origin = origin;
        ray.TMin = 0.0f;
        ray.Direction = dir;
        ray.TMax = 1.0e30f;
        TraceRay(sceneTlas, RAY_FLAG_FORCE_OPAQUE, 0xFF, 0, 0, 0, ray, payload);
        ++segments;
        if (payload.t < 0.0f) break;
        if (any(sigma != (float3)0.0f)) flux *= beerLambert(sigma, payload.t);
        SurfaceHit h = sceneSurfaceHit(payload.instance, payload.primitive, payload.barycentrics);
        float3 x = origin + payload.t * dir;
        float3 ng = dot(h.shadingNormal, h.geometricNormal) < 0.0f ? -h.geometricNormal : h.geometricNormal;
        float eps = rayEpsilon(x);
        if (sceneMaterialIsSpecular(h.material)) {
            // A direction belongs to the layer owning the first specular instance on it (forward_body.glsl).
            if (events == 0u && (payload.instance >= pc.instanceCount ||
                                 !causticLayerOwns(owners, m, pc.instanceCount, payload.instance)))
                break;
            if (events >= pc.maxDepth) break;
            SpecularEvent ev = sampleSpecularEvent(dir, h.shadingNormal, h.optics, rngNextFloat3(rng), kTransportImportance);
            if (ev.kind == kEventAbsorbed) break;
            if (ev.kind != kEventDiffuse) {
                ++events;
                flux *= ev.weight;
                throughput *= ev.weight;
                dir = ev.direction;
                sigma = ev.insideMedium ? volumeSigmaA(h.material.attenuationColor, h.material.attenuationDistance)
                                        : (float3)0.0f;
                origin = x + (dot(dir, ng) > 0.0f ? ng : -ng) * eps;
                if ((pc.flags & 1u) != 0u && events >= 2u) {
                    float survive = min(1.0f, max(throughput.x, max(throughput.y, throughput.z)));
                    if (rngNextFloat(rng) >= survive) break;
                    flux /= survive;
                    throughput /= survive;
                }
                continue;
            }
        }
        if (events == 0u) break;
        float3 nFacing = dot(h.shadingNormal, dir) < 0.0f ? h.shadingNormal : -h.shadingNormal;
        if (m.orthographic == 0u) flux *= lightRangeWindow(length(x - m.origin), m.range);
        if (max(flux.x, max(flux.y, flux.z)) <= 0.0f) break;
        BrdfMaterial brdf = receiverBrdfMaterial(h);
        uint slot;
        statAdd(kStatStoredHitAttempts, 1u, slot);
        if (slot < pc.maxStoredHits) storeCausticHit(hits, slot, x, h.objectId, nFacing, m.light, flux, -dir, brdf);
        splatFirstType(camera, x, nFacing, h.objectId, flux, -dir, brdf);
        break;
    }
    statAdd(kStatForwardSegments, segments);
}
