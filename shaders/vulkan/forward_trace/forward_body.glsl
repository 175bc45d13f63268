// Forward caustic trace (paper 3.2, Figure 4): one launch per (emitting map texel, sample), the texels
// listed per layer by caustics.emitters (caustic_maps/emitters.comp), the launches laid out per layer
// by caustics.photonPlan (caustic_maps/photon_plan.comp). Shared by forward.rgen (float atomics) and
// forward_fixed.rgen (fixed-point atomics).
#extension GL_EXT_ray_tracing : require
#extension GL_EXT_samplerless_texture_functions : require
#include "scene/scene.glsl"
#include "scene/camera.glsl"
#include "common/emission.h"
#include "common/rng.h"
#include "common/volume.h"
#include "caustic_maps/caustic_map.glsl"
#include "caustic_maps/emitter_list.glsl"
#include "caustic_maps/layer_plan.glsl"
#include "forward_trace/caustic_hit.glsl"

layout(set = 1, binding = 0) uniform CameraBlock { CameraConstants camera; };
layout(set = 1, binding = 1, std430) readonly buffer Maps { CausticMap maps[]; };
layout(set = 1, binding = 2, std430) readonly buffer Emitters { uint emitters[]; };
layout(set = 1, binding = 3) uniform texture2D gLinearDepth;
layout(set = 1, binding = 4) uniform utexture2D gObjectId;
layout(set = 1, binding = 6, std430) buffer Hits { CausticHitRecord hits[]; };
layout(set = 1, binding = 7, std430) buffer Stats { uint stats[]; };
layout(set = 1, binding = 8, std430) buffer Plans { CausticLayerPlan plans[]; };
layout(set = 1, binding = 9, std430) readonly buffer Owners { uint owners[]; };
#define RADIANCE_SET 1
#define RADIANCE_BINDING 5
#include "forward_trace/radiance_atomics.glsl"

layout(push_constant) uniform Push {
    uint mapSize;
    uint layers;
    uint instanceCount;     // row length of owners
    uint maxDepth;
    uint frame;
    uint flags;             // bit 0: Russian roulette
    uint maxStoredHits;
    uint pad;
} pc;

layout(location = 0) rayPayloadEXT TracePayload payload;

// The receiver's BRDF (shaders/common/bsdf.h). A specular material reaches here only through its
// diffuse layer, whose Fresnel/metallic/transmission weights the sampled event already applied.
BrdfMaterial receiverBrdfMaterial(SurfaceHit h) {
    GpuMaterial m = h.material;
    if (sceneMaterialIsSpecular(m)) return lambertOnlyBrdfMaterial(h.baseColor);
    return makeBrdfMaterial(h.baseColor, m.metallic, m.roughness, m.transmission, gltfDielectricF0(m.specular, m.ior));
}

// Light-tracing estimator (shaders/common/camera.h) with the camera G-buffer as the visibility test
// (paper Figure 4b): same object and a depth within the pixel's footprint on the surface.
void splatFirstType(CausticHit hit) {
    vec3 x = hit.position;
    vec3 nFacing = hit.normal;
    PinholeCamera cam = cameraPinhole(camera);
    CameraProjection pr = cameraProject(camera, x);
    if (!pr.valid || pr.depth < camera.clip.x) return;
    vec3 toEye = (cam.eye - x) / pr.distance;
    float cosSurface = dot(nFacing, toEye);
    if (cosSurface <= 0.0) return;
    ivec2 px = ivec2(pr.pixel);
    if (texelFetch(gObjectId, px, 0).r != hit.objectId) return;
    float gDepth = texelFetch(gLinearDepth, px, 0).r;
    // Depth varies across one pixel by (pixel footprint) x tan(view angle); allow that plus 0.1 %.
    float footprint = 2.0 * cam.tanHalfFovY / cam.height;
    float tanView = min(sqrt(max(0.0, 1.0 - cosSurface * cosSurface)) / cosSurface, 20.0);
    if (abs(pr.depth - gDepth) > gDepth * (1e-3 + 1.5 * footprint * tanView)) return;
    float factor = pinholeSplatFactor(cam, pr.cosTheta, cosSurface, pr.distance);
    addRadiance(uint(px.y) * camera.frame.x + uint(px.x), causticHitReflectedFlux(hit, toEye) * factor);
    atomicAdd(stats[kStatSplats], 1u);
}

void main() {
    uint launch = gl_LaunchIDEXT.x;
    if (launch == 0u) atomicAdd(stats[kStatDispatchedTexels], gl_LaunchSizeEXT.x);
    // The layer whose launch range holds this launch; a direct (not indirect) dispatch covers an upper
    // bound, and launches past the last range idle.
    int layer = -1;
    for (uint k = 0u; k < pc.layers && layer < 0; ++k)
        if (launch - plans[k].launchOffset < plans[k].launches) layer = int(k);
    if (layer < 0) return;
    uint local = launch - plans[layer].launchOffset;
    uint emitterCount = plans[layer].emitters;
    uint packed = emitters[uint(layer) * pc.mapSize * pc.mapSize + local % emitterCount];
    uint tx = emitterTexel(packed).x;
    uint ty = emitterTexel(packed).y;
    uint sampleIndex = local / emitterCount;
    float raysPerTexel = plans[layer].raysPerTexel;
    CausticMap m = maps[layer];

    // The key of a texel's random stream: its light and, for a light's second and later layers, the
    // layer's number (the first layer keeps the light alone, as with one map per light).
    Rng rng = rngCreate(ty * pc.mapSize + tx, m.light | (m.cluster << 6), sampleIndex, pc.frame);
    // Fractional rays per texel: sample s of a texel is emitted with probability clamp(r - s, 0, 1),
    // so a texel emits r rays on average; each carries 1/r of the texel's flux (unbiased).
    float emitProbability = clamp(raysPerTexel - float(sampleIndex), 0.0, 1.0);
    if (emitProbability < 1.0 && rngNextFloat(rng) >= emitProbability) return;
    atomicAdd(stats[kStatRaysPerLight + m.light], 1u);
    atomicAdd(plans[layer].emitted, 1u);

    vec2 coord = vec2(tx, ty) + rngNextFloat2(rng);
    float n = float(pc.mapSize);
    vec3 origin, dir, flux;
    if (m.orthographic != 0u) {
        vec2 q = m.extent * (2.0 * coord / n - 1.0);
        origin = m.origin + q.x * m.right + q.y * m.up;
        dir = m.forward;
        flux = m.intensity * photonFluxOrthographic(1.0, orthographicTexelArea(m.extent, n), raysPerTexel);
    } else {
        vec2 q = perspectiveMapPlanePoint(coord, n, m.extent);
        origin = m.origin;
        dir = normalize(m.forward + q.x * m.right + q.y * m.up);
        float omega = perspectiveTexelSolidAngle(uvec2(tx, ty), n, m.extent);
        float falloff = m.cosOuter > -1.0 ? spotAttenuation(dot(dir, m.spotAxis), m.cosInner, m.cosOuter) : 1.0;
        flux = m.intensity * (falloff * photonFluxPerspective(1.0, omega, raysPerTexel));
    }
    if (max(flux.x, max(flux.y, flux.z)) <= 0.0) return;

    vec3 sigma = vec3(0.0);
    vec3 throughput = vec3(1.0);
    uint events = 0u;
    uint segments = 0u;   // one atomic per path, not per segment (kStatForwardSegments)
    for (uint vertex = 0u; vertex <= pc.maxDepth + 1u; ++vertex) {
        payload.t = -1.0;
        traceRayEXT(sceneTlas, gl_RayFlagsOpaqueEXT, 0xFF, 0, 0, 0, origin, 0.0, dir, 1.0e30, 0);
        ++segments;
        if (payload.t < 0.0) break;
        if (sigma != vec3(0.0)) flux *= beerLambert(sigma, payload.t);
        SurfaceHit h = sceneSurfaceHit(payload.instance, payload.primitive, payload.barycentrics);
        vec3 x = origin + payload.t * dir;
        vec3 ng = dot(h.shadingNormal, h.geometricNormal) < 0.0 ? -h.geometricNormal : h.geometricNormal;
        float eps = rayEpsilon(x);
        if (sceneMaterialIsSpecular(h.material)) {
            // A direction belongs to the layer owning the first specular instance on it; another
            // layer of the light emits it (caustic_map_plan.h), or none when that one is hidden.
            if (events == 0u && (payload.instance >= pc.instanceCount ||
                                 !CAUSTIC_LAYER_OWNS(owners, m, pc.instanceCount, payload.instance)))
                break;
            if (events >= pc.maxDepth) break;
            SpecularEvent ev = sampleSpecularEvent(dir, h.shadingNormal, h.optics, rngNextFloat3(rng), kTransportImportance);
            if (ev.kind == kEventAbsorbed) break;
            if (ev.kind != kEventDiffuse) {
                ++events;
                flux *= ev.weight;
                throughput *= ev.weight;
                dir = ev.direction;
                sigma = ev.insideMedium ? volumeSigmaA(h.material.attenuationColor, h.material.attenuationDistance) : vec3(0.0);
                origin = x + (dot(dir, ng) > 0.0 ? ng : -ng) * eps;
                if ((pc.flags & 1u) != 0u && events >= 2u) {
                    // Russian roulette by path throughput; survivors are reweighted (unbiased).
                    float survive = min(1.0, max(throughput.x, max(throughput.y, throughput.z)));
                    if (rngNextFloat(rng) >= survive) break;
                    flux /= survive;
                    throughput /= survive;
                }
                continue;
            }
        }
        if (events == 0u) break;   // direct light, not a caustic
        vec3 nFacing = dot(h.shadingNormal, dir) < 0.0 ? h.shadingNormal : -h.shadingNormal;
        // The light's range window at the receiver, as direct light applies it (no caustic beyond range).
        if (m.orthographic == 0u) flux *= lightRangeWindow(length(x - m.origin), m.range);
        if (max(flux.x, max(flux.y, flux.z)) <= 0.0) break;
        CausticHit hit = makeCausticHit(x, h.objectId, nFacing, m.light, flux, -dir, receiverBrdfMaterial(h));
        uint slot = atomicAdd(stats[kStatStoredHitAttempts], 1u);
        if (slot < pc.maxStoredHits) hits[slot] = packCausticHit(hit);
        splatFirstType(hit);
        break;
    }
    atomicAdd(stats[kStatForwardSegments], segments);
}
