#ifndef CAUSTICS_PASS_FORWARD_H
#define CAUSTICS_PASS_FORWARD_H
// caustics.forward in the shared dialect (paper 3.2, Figure 4; docs/shaders.md): one launch per
// (emitting map texel, sample), the texels listed per layer by caustics.emitters, the launches laid out
// per layer by caustics.photonPlan. A launch emits a photon from its texel, follows it through the
// specular chain (iterated here: the closest-hit shader only reports the surface, so recursion depth
// stays 1), and at the first diffuse receiver stores the hit for the second type's gather and splats
// its first-type radiance into the camera pixel the G-buffer confirms (paper Figure 4b).
// Entries: forward.rgen / forward_fixed.rgen / forward_fixed64.rgen (float, 32-bit and 64-bit
// fixed-point radiance atomics; docs/caustics.md, "Fixed point"), forward*.hlsl; the scene trace's hit
// and miss are passes/scene_trace/shaders/trace.rchit, trace.rmiss, trace.hlsl.
#include "common/bsdf.h"
#include "common/camera.h"
#include "common/caster_motion.h"
#include "common/caustic_hit.h"
#include "common/caustic_map.h"
#include "common/emission.h"
#include "common/layer_plan.h"
#include "common/rng.h"
#include "common/scene.h"
#include "common/volume.h"

CAUSTICS_SHARED_BEGIN
// Push constants (forward_bindings.h), 32 bytes.
struct ForwardParams {
    uint mapSize;
    uint layers;
    uint instanceCount;   // row length of the owners table
    uint maxDepth;        // specular events a path may have
    uint frame;           // the frame's random key
    uint flags;           // kForwardRussianRoulette, kForwardCasterMotion
    uint maxStoredHits;   // records the hit buffer holds
    uint pad;
};
CAUSTICS_CONST uint kForwardRussianRoulette = 1u;
// Accumulate where each splat would have landed under last frame's instance transforms (instanceMotion,
// casterMotion; docs/caustics.md "Moving casters").
CAUSTICS_CONST uint kForwardCasterMotion = 2u;

// A photon leaving a map texel: its origin, unit direction and flux (lm per channel).
struct ForwardPhoton {
    float3 origin;
    float3 dir;
    float3 flux;
};

// The photon of sample point `coord` (texel + jitter) of map m (side n texels), each photon carrying
// 1 / raysPerTexel of its texel's flux (common/emission.h; docs/physics.md).
CAUSTICS_FN ForwardPhoton emitPhoton(CausticMap m, float2 coord, uint2 texel, float n, float raysPerTexel) {
    ForwardPhoton p;
    if (m.orthographic != 0u) {
        float2 q = m.extent * (2.0f * coord / n - 1.0f);
        p.origin = m.origin + q.x * m.right + q.y * m.up;
        p.dir = m.forward;
        p.flux = m.intensity * photonFluxOrthographic(1.0f, orthographicTexelArea(m.extent, n), raysPerTexel);
    } else {
        float2 q = perspectiveMapPlanePoint(coord, n, m.extent);
        p.origin = m.origin;
        p.dir = normalize(m.forward + q.x * m.right + q.y * m.up);
        float omega = perspectiveTexelSolidAngle(texel, n, m.extent);
        float falloff = m.cosOuter > -1.0f ? spotAttenuation(dot(p.dir, m.spotAxis), m.cosInner, m.cosOuter) : 1.0f;
        p.flux = m.intensity * (falloff * photonFluxPerspective(1.0f, omega, raysPerTexel));
    }
    return p;
}

// The receiver's BRDF (shaders/common/bsdf.h). A specular material reaches here only through its
// diffuse layer, whose Fresnel/metallic/transmission weights the sampled event already applied.
CAUSTICS_FN BrdfMaterial receiverBrdfMaterial(SurfaceHit h) {
    GpuMaterial m = h.material;
    if (sceneMaterialIsSpecular(m)) return lambertOnlyBrdfMaterial(h.baseColor);
    return makeBrdfMaterial(h.baseColor, m.metallic, m.roughness, m.transmission, gltfDielectricF0(m.specular, m.ior));
}

// The G-buffer's visibility test of a splat (paper Figure 4b, with the same object as the second
// condition): the splat's depth along the optical axis within the pixel's footprint on the surface
// of the G-buffer's depth gDepth. Depth varies across one pixel by (pixel footprint) x tan(view
// angle); allow that plus 0.1 %.
CAUSTICS_FN bool splatDepthMatches(PinholeCamera cam, float depth, float gDepth, float cosSurface) {
    float footprint = 2.0f * cam.tanHalfFovY / cam.height;
    float tanView = min(sqrt(max(0.0f, 1.0f - cosSurface * cosSurface)) / cosSurface, 20.0f);
    return !(abs(depth - gDepth) > gDepth * (1e-3f + 1.5f * footprint * tanView));
}

CAUSTICS_SHARED_END

// The pass's resources: generated from forward_bindings.h (one declaration per radiance word type);
// a C++ caller defines the accessors the pure functions below read.
#if defined(CAUSTICS_LANG_CPP)
namespace caustics::shader {
CausticLayerPlan plansLoad(uint i);
}  // namespace caustics::shader
#elif !defined(CAUSTICS_FIXED_POINT) && !defined(CAUSTICS_FIXED_POINT_64)
#include "bindings/forward.h"
#elif defined(CAUSTICS_FIXED_POINT_64)
#include "bindings/forward_fixed64.h"
#else
#include "bindings/forward_fixed.h"
#endif

CAUSTICS_SHARED_BEGIN
// The layer whose launch range holds `launch`, or -1: a direct (not indirect) dispatch covers an
// upper bound, and launches past the last range idle.
CAUSTICS_FN int forwardLayerOf(uint launch, uint layers) {
    int layer = -1;
    for (uint k = 0u; k < layers && layer < 0; ++k)
        if (launch - plansLoad(k).launchOffset < plansLoad(k).launches) layer = int(k);
    return layer;
}
CAUSTICS_SHARED_END

#if !defined(CAUSTICS_LANG_CPP)
// The thread function and what it reaches per API: the scene trace, the radiance atomics (which
// read the generated radianceWords and stats; docs/caustics.md, "Fixed point"), texel reads, and the
// layer plan's emitted counter (a member of a struct element, so no generated accessor).
#include "common/resources.h"

#include "common/scene_trace.h"

// The radiance atomics (float, or 32-/64-bit fixed point) on the generated radianceWords.
#include "common/radiance_atomics.h"
#if defined(CAUSTICS_LANG_GLSL)
#define FORWARD_COUNT_EMITTED(layer) atomicAdd(plans[layer].emitted, 1u)
#else
#define FORWARD_COUNT_EMITTED(layer) plans.InterlockedAdd(32u * (layer) + 20u, 1u)   // CausticLayerPlan::emitted
#endif

// Light-tracing estimator (shaders/common/camera.h) with the camera G-buffer as the visibility test
// (paper Figure 4b): same object and a depth within the pixel's footprint on the surface.
// The splat's caster motion: the receiver shift summed into its pixel's words, and one photon counted.
void addCasterMotion(uint pixel, float3 shift) {
    int3 q = casterMotionFixed(shift);
    casterMotionAtomicAdd(kCasterMotionWords * pixel, uint(q.x));
    casterMotionAtomicAdd(kCasterMotionWords * pixel + 1u, uint(q.y));
    casterMotionAtomicAdd(kCasterMotionWords * pixel + 2u, uint(q.z));
    casterMotionAtomicAdd(kCasterMotionWords * pixel + 3u, 1u);
}

// Where world point x on instance i was last frame (its rows of prev x inverse(current)).
float3 instancePreviousPosition(uint instance, float3 x) {
    uint r = kCasterMotionRowsPerInstance * instance;
    return instanceRowsApply(instanceMotionLoad(r), instanceMotionLoad(r + 1u), instanceMotionLoad(r + 2u), x);
}

void splatFirstType(CausticHit hit, float4 receiverShift) {
    float3 x = hit.position;
    float3 nFacing = hit.normal;
    PinholeCamera cam = cameraPinhole(camera);
    CameraProjection pr = cameraProject(camera, x);
    if (!pr.valid || pr.depth < camera.clip.x) return;
    float3 toEye = (cam.eye - x) / pr.distance;
    float cosSurface = dot(nFacing, toEye);
    if (cosSurface <= 0.0f) return;
    int2 px = int2(pr.pixel);
    if (CAUSTICS_TEXEL_UINT(gObjectId, px) != hit.objectId) return;
    float gDepth = CAUSTICS_TEXEL(gLinearDepth, px).r;
    if (!splatDepthMatches(cam, pr.depth, gDepth, cosSurface)) return;
    float factor = pinholeSplatFactor(cam, pr.cosTheta, cosSurface, pr.distance);
    uint pixel = uint(px.y) * camera.frame.x + uint(px.x);
    addRadiance(pixel, causticHitReflectedFlux(hit, toEye) * factor);
    if (receiverShift.w > 0.0f) addCasterMotion(pixel, receiverShift.xyz);
    statsAtomicAdd(kStatSplats, 1u);
}

void forwardLaunch(uint launch, uint launchCount) {
    if (launch == 0u) statsAtomicAdd(kStatDispatchedTexels, launchCount);
    int layer = forwardLayerOf(launch, params.layers);
    if (layer < 0) return;
    CausticLayerPlan plan = plansLoad(uint(layer));
    uint local = launch - plan.launchOffset;
    uint emitterCount = plan.emitters;
    uint packed = emittersLoad(uint(layer) * params.mapSize * params.mapSize + local % emitterCount);
    uint tx = emitterTexel(packed).x;
    uint ty = emitterTexel(packed).y;
    uint sampleIndex = local / emitterCount;
    float raysPerTexel = plan.raysPerTexel;
    CausticMap m = mapsLoad(uint(layer));

    // The key of a texel's random stream: its light and, for a light's second and later layers, the
    // layer's number (the first layer keeps the light alone, as with one map per light).
    Rng rng = rngCreate(ty * params.mapSize + tx, m.light | (m.cluster << 6), sampleIndex, params.frame);
    // Fractional rays per texel: sample s of a texel is emitted with probability clamp(r - s, 0, 1),
    // so a texel emits r rays on average; each carries 1/r of the texel's flux (unbiased).
    float emitProbability = clamp(raysPerTexel - float(sampleIndex), 0.0f, 1.0f);
    if (emitProbability < 1.0f && rngNextFloat(rng) >= emitProbability) return;
    statsAtomicAdd(kStatRaysPerLight + m.light, 1u);
    FORWARD_COUNT_EMITTED(uint(layer));

    float2 coord = float2(tx, ty) + rngNextFloat2(rng);
    ForwardPhoton photon = emitPhoton(m, coord, uint2(tx, ty), float(params.mapSize), raysPerTexel);
    float3 origin = photon.origin;
    float3 dir = photon.dir;
    float3 flux = photon.flux;
    if (max(flux.x, max(flux.y, flux.z)) <= 0.0f) return;

    float3 sigma = splat3(0.0f);
    float3 throughput = splat3(1.0f);
    uint events = 0u;
    // Caster motion (kForwardCasterMotion): last frame's position of the photon's last moving specular
    // vertex minus this frame's; a static specular vertex after it passes the shift on (first order).
    bool motion = (params.flags & kForwardCasterMotion) != 0u;
    float3 vertexShift = splat3(0.0f);
    uint segments = 0u;   // one atomic per path, not per segment (kStatForwardSegments)
    for (uint vertex = 0u; vertex <= params.maxDepth + 1u; ++vertex) {
        TracePayload hit = traceScene(origin, 0.0f, dir, 1.0e30f);
        ++segments;
        if (hit.t < 0.0f) break;
        if (dot(sigma, sigma) > 0.0f) flux *= beerLambert(sigma, hit.t);   // inside an absorbing medium
        SurfaceHit h = sceneSurfaceHit(hit.instance, hit.primitive, hit.barycentrics);
        float3 x = origin + hit.t * dir;
        float3 ng = dot(h.shadingNormal, h.geometricNormal) < 0.0f ? -h.geometricNormal : h.geometricNormal;
        float eps = rayEpsilon(x);
        if (sceneMaterialIsSpecular(h.material)) {
            // A direction belongs to the layer owning the first specular instance on it; another
            // layer of the light emits it (caustic_map_plan.h), or none when that one is hidden.
            if (events == 0u && (hit.instance >= params.instanceCount ||
                                 !causticLayerOwnsEntry(m, ownersLoad(m.ownerRow * params.instanceCount + hit.instance))))
                break;
            if (events >= params.maxDepth) break;
            SpecularEvent ev = sampleSpecularEvent(dir, h.shadingNormal, h.optics, rngNextFloat3(rng), kTransportImportance);
            if (ev.kind == kEventAbsorbed) break;
            if (ev.kind != kEventDiffuse) {
                ++events;
                if (motion && hit.instance < params.instanceCount) {
                    float3 shift = instancePreviousPosition(hit.instance, x) - x;
                    if (dot(shift, shift) > 1e-10f) vertexShift = shift;   // over 10 um: not rounding
                }
                flux *= ev.weight;
                throughput *= ev.weight;
                dir = ev.direction;
                sigma = ev.insideMedium ? volumeSigmaA(h.material.attenuationColor, h.material.attenuationDistance)
                                        : splat3(0.0f);
                origin = x + (dot(dir, ng) > 0.0f ? ng : -ng) * eps;
                if ((params.flags & kForwardRussianRoulette) != 0u && events >= 2u) {
                    // Russian roulette by path throughput; survivors are reweighted (unbiased).
                    float survive = min(1.0f, max(throughput.x, max(throughput.y, throughput.z)));
                    if (rngNextFloat(rng) >= survive) break;
                    flux /= survive;
                    throughput /= survive;
                }
                continue;
            }
        }
        if (events == 0u) break;   // direct light, not a caustic
        float3 nFacing = dot(h.shadingNormal, dir) < 0.0f ? h.shadingNormal : -h.shadingNormal;
        // The light's range window at the receiver, as direct light applies it (no caustic beyond range).
        if (m.orthographic == 0u) flux *= lightRangeWindow(length(x - m.origin), m.range);
        if (max(flux.x, max(flux.y, flux.z)) <= 0.0f) break;
        CausticHit stored = makeCausticHit(x, h.objectId, nFacing, m.light, flux, -dir, receiverBrdfMaterial(h));
        uint slot = statsAtomicAdd(kStatStoredHitAttempts, 1u);
        if (slot < params.maxStoredHits) hitsStore(slot, packCausticHit(stored));
        // The receiver shift where the photon's chain moved (docs/caustics.md "Moving casters"); w = 0: none.
        float4 shift = float4(0.0f, 0.0f, 0.0f, 0.0f);
        if (motion && dot(vertexShift, vertexShift) > 0.0f) shift = float4(casterMotionReceiverShift(vertexShift, dir, nFacing), 1.0f);
        splatFirstType(stored, shift);
        break;
    }
    statsAtomicAdd(kStatForwardSegments, segments);
}
#endif  // !CAUSTICS_LANG_CPP

#endif  // CAUSTICS_PASS_FORWARD_H
