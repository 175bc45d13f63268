// Backward pass (paper 3.3, Figure 5; mirror of shaders/vulkan/backward_trace/backward.rgen): from
// every camera pixel of caustics.specularPixels' list, trace the specular chain to the first diffuse
// hit; that hit becomes an integration sphere, appended with its AABB in the sphere BLAS at the next
// slot of a counter (slots past the capacity are dropped and counted). The pixel's ray differentials
// (Igehy 1999) follow the chain, so the sphere's radius is the pixel's real footprint on the receiver
// (docs/caustics.md).
#include "scene/scene.hlsli"
#include "scene/camera.hlsli"
#include "common/gather_disk.h"
#include "common/rng.h"
#include "common/volume.h"
#include "forward_trace/caustic_hit.hlsli"
#include "backward_trace/surface_derivatives.hlsli"
#include "backward_trace/sphere_list.hlsli"
#include "common/scene_trace.h"

struct CameraBlock { CameraConstants camera; };
ConstantBuffer<CameraBlock> cameraBlock : register(b0, space1);
RWByteAddressBuffer spheres : register(u3, space1);
RWByteAddressBuffer sphereAabbs : register(u4, space1);   // D3D12_RAYTRACING_AABB per slot, 24 bytes
RWByteAddressBuffer stats : register(u5, space1);
ByteAddressBuffer specularPixels : register(t6, space1);

struct Push {
    uint radiusPolicy;   // 0 pixel footprint, 1 fixed world radius
    float radiusScale;
    float worldRadius;
    uint maxDepth;
    uint frame;
    float minMagnification;   // footprint width clamp, relative to the unfolded pixel width
    float maxMagnification;
    float minRadius;          // metres
    float maxRadius;          // metres
    uint sphereCapacity;      // AABB slots of the sphere BLAS build (caustics.sphereBlas)
};
ConstantBuffer<Push> pc : register(b0, space999);

void writeSphere(uint slot, uint pixel, float3 centre, float radius, float3 transmittance, uint objectId, float3 normal,
                 float3 outgoing) {
    uint o = kCausticSphereBytes * slot;
    spheres.Store4(o, uint4(asuint(centre), asuint(radius)));
    spheres.Store4(o + 16u, uint4(asuint(transmittance), objectId));
    spheres.Store4(o + 32u, uint4(asuint(normal), pixel));
    spheres.Store4(o + 48u, uint4(asuint(outgoing), 0u));
}

// The gather disk lies inside the radius-ball: its box (min xyz, max xyz) bounds every point the
// any-hit accepts; the primitive index is the slot.
void writeSphereAabb(uint slot, float3 c, float r) {
    uint o = 24u * slot;
    sphereAabbs.Store3(o, asuint(c - r));
    sphereAabbs.Store3(o + 12u, asuint(c + r));
}

// Shrinks `radius` so the disk at x (receiver normal n facing the camera path) stays on this side of
// any wall (as clampRadiusAtWalls in backward.rgen).
float clampRadiusAtWalls(float3 x, float3 n, float radius) {
    float3 t = normalize(abs(n.x) < 0.9f ? cross(n, float3(1.0f, 0.0f, 0.0f)) : cross(n, float3(0.0f, 1.0f, 0.0f)));
    float3 b = cross(n, t);
    float3 origin = x + n * max(kGatherDiskThickness * radius, rayEpsilon(x));
    float reach = radius / kWallProbeCosHalfStep;
    float nearest = reach;
    for (uint k = 0u; k < kWallProbeCount; ++k) {
        float phi = kTwoPi * float(k) / float(kWallProbeCount);
        TracePayload probe = traceScene(origin, 0.0f, cos(phi) * t + sin(phi) * b, reach);
        if (probe.t >= 0.0f) nearest = min(nearest, probe.t);
    }
    return min(radius, kWallProbeCosHalfStep * nearest);
}

[shader("raygeneration")]
void main() {
    CameraConstants camera = cameraBlock.camera;
    uint launch = DispatchRaysIndex().x;
    if (launch == 0u) stats.InterlockedAdd(4u * kStatBackwardLaunches, DispatchRaysDimensions().x);
    // Without indirect dispatch the grid is the list's capacity (W x H): launches past its length idle.
    if (launch >= min(stats.Load(4u * kStatSpecularPixels), pc.sphereCapacity)) return;   // the list's length
    uint pixel = specularPixels.Load(4u * launch);
    uint2 p = uint2(pixel % camera.frame.x, pixel / camera.frame.x);

    Rng rng = rngCreate(pixel, 0x5eedu, 1u, pc.frame);
    PinholeCamera cam = cameraPinhole(camera);
    float3 origin = cam.eye;
    // A jittered position inside the pixel: accumulated frames converge to the pixel's mean.
    float2 pixelPosition = float2(p) + rngNextFloat2(rng);
    // The host's projection jitter shifts the image against the centred pinhole (cameraJitter).
    float2 pinholePosition = pixelPosition - cameraJitter(camera);
    float3 dir = cameraRayDirection(cam, pinholePosition);
    RayDifferential rd = pinholeRayDifferential(cam, pinholePosition);
    float3 throughput = (float3)1.0f;
    float3 sigma = (float3)0.0f;
    float pathLength = 0.0f;
    uint events = 0u;
    for (uint vertex = 0u; vertex <= pc.maxDepth + 1u; ++vertex) {
        TracePayload payload = traceScene(origin, vertex == 0u ? camera.clip.x : 0.0f, dir, 1.0e30f);
        if (payload.t < 0.0f) break;
        pathLength += payload.t;
        if (any(sigma != (float3)0.0f)) throughput *= beerLambert(sigma, payload.t);
        SurfaceHit h = sceneSurfaceHit(payload.instance, payload.primitive, payload.barycentrics);
        float3 x = origin + payload.t * dir;
        float3 ng = dot(h.shadingNormal, h.geometricNormal) < 0.0f ? -h.geometricNormal : h.geometricNormal;
        rd = transferRayDifferential(rd, dir, payload.t, h.geometricNormal);
        if (sceneMaterialIsSpecular(h.material)) {
            if (events >= pc.maxDepth) break;
            SpecularEvent ev = sampleSpecularEvent(dir, h.shadingNormal, h.optics, rngNextFloat3(rng), kTransportRadiance);
            if (ev.kind == kEventAbsorbed) break;
            if (ev.kind != kEventDiffuse) {
                ++events;
                throughput *= ev.weight;
                float3 dNdx, dNdy;
                shadingNormalDerivatives(sceneSurfaceDerivatives(payload.instance, payload.primitive, payload.barycentrics), rd,
                                         dNdx, dNdy);
                rd = scatterRayDifferential(rd, dir, ev, h.shadingNormal, dNdx, dNdy, h.optics);
                dir = ev.direction;
                sigma = ev.insideMedium ? volumeSigmaA(h.material.attenuationColor, h.material.attenuationDistance)
                                        : (float3)0.0f;
                origin = x + (dot(dir, ng) > 0.0f ? ng : -ng) * rayEpsilon(x);
                continue;
            }
        }
        // Seen directly. On the specular surface itself (its diffuse lobe) the first-type pass splats into
        // this pixel already. A ray whose jitter crossed the glass's silhouette onto a diffuse surface
        // does not: that pass splats only where the G-buffer (here the glass) shows the receiver. Its
        // sphere gathers the first-type light with throughput 1 (docs/caustics.md, "Glass edges").
        if (events == 0u && sceneMaterialIsSpecular(h.material)) break;
        float3 nFacing = dot(h.shadingNormal, dir) < 0.0f ? h.shadingNormal : -h.shadingNormal;
        float radius = pc.worldRadius;
        if (pc.radiusPolicy == 0u) {
            GatherRadiusLimits limits;
            limits.scale = pc.radiusScale;
            limits.minMagnification = pc.minMagnification;
            limits.maxMagnification = pc.maxMagnification;
            limits.minRadius = pc.minRadius;
            limits.maxRadius = pc.maxRadius;
            radius = gatherDiskRadius(rayFootprintArea(rd), pathLength * sqrt(pinholePixelArea(cam)), limits);
        }
        radius = max(clampRadiusAtWalls(x, nFacing, radius), min(pc.minRadius, radius));
        // kStatSpheres counts every sphere, dropped or not: the host sizes later frames from it.
        uint slot;
        stats.InterlockedAdd(4u * kStatSpheres, 1u, slot);
        if (slot >= pc.sphereCapacity) {
            stats.InterlockedAdd(4u * kStatSpheresDropped, 1u);
            return;
        }
        writeSphere(slot, pixel, x, radius, throughput, h.objectId, nFacing, -dir);
        writeSphereAabb(slot, x, radius);
        return;
    }
}
