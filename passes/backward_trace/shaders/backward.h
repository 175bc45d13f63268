#ifndef CAUSTICS_PASS_BACKWARD_H
#define CAUSTICS_PASS_BACKWARD_H
// caustics.backward in the shared dialect (paper 3.3, Figure 5; docs/shaders.md): one launch per entry
// of caustics.specularPixels' list, a camera pixel whose G-buffer surface is specular. The launch traces
// through the specular chain (radiance transport) to the first diffuse hit; that hit becomes an
// integration sphere, appended with its AABB in the sphere BLAS at the next slot of a counter. Slots at
// or past the capacity are dropped and counted (docs/caustics.md, "Second-type cost"); the AABBs past
// the count are refused by the intersection shader (gather.h). The pixel's ray differentials (Igehy
// 1999) follow the chain, so the sphere's radius is the pixel's real footprint on the receiver
// (docs/caustics.md "Second-type footprint").
// Entries: backward.rgen, backward.hlsl; the scene trace's hit and miss are scene_trace's trace.rchit /
// trace.rmiss (one TracePayload for every scene trace).
#include "common/camera.h"
#include "common/caustic_hit.h"
#include "common/gather_disk.h"
#include "common/rng.h"
#include "common/scene.h"
#include "common/surface_derivatives.h"
#include "common/volume.h"

CAUSTICS_SHARED_BEGIN
// Push constants (backward_bindings.h), 40 bytes.
struct BackwardParams {
    uint radiusPolicy;        // kBackwardRadiusFootprint or kBackwardRadiusWorld
    float radiusScale;
    float worldRadius;        // metres, kBackwardRadiusWorld
    uint maxDepth;            // specular events a path may have
    uint frame;               // the frame's random key
    float minMagnification;   // footprint width clamp, relative to the unfolded pixel width
    float maxMagnification;
    float minRadius;          // metres
    float maxRadius;          // metres
    uint sphereCapacity;      // AABB slots of the sphere BLAS build (caustics.sphereBlas)
};
CAUSTICS_CONST uint kBackwardRadiusFootprint = 0u;
CAUSTICS_CONST uint kBackwardRadiusWorld = 1u;

// The tangent frame's first axis of the wall probes around normal n.
CAUSTICS_FN float3 wallProbeTangent(float3 n) {
    return normalize(abs(n.x) < 0.9f ? cross(n, float3(1.0f, 0.0f, 0.0f)) : cross(n, float3(0.0f, 1.0f, 0.0f)));
}
CAUSTICS_SHARED_END

#if !defined(CAUSTICS_LANG_CPP)
// The thread function and what it reaches: the generated resources and the scene trace.
#include "bindings/backward.h"   // generated from passes/backward_trace/backward_bindings.h
#include "common/scene_trace.h"

// Shrinks `radius` so the disk at x (receiver normal n facing the camera path) stays on this side of
// any wall: kWallProbeCount rays in the tangent plane, a quarter radius above the surface (the disk's
// thickness), find the nearest occluder within the radius.
float clampRadiusAtWalls(float3 x, float3 n, float radius) {
    float3 t = wallProbeTangent(n);
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

// Appends the sphere at the counter's next slot with its box (the gather disk lies inside the
// radius-ball: the box bounds every point the any-hit accepts). kStatSpheres counts every sphere,
// dropped or not: the host sizes later frames from it.
void appendSphere(CausticSphere s) {
    uint slot = statsAtomicAdd(kStatSpheres, 1u);
    if (slot >= params.sphereCapacity) {
        statsAtomicAdd(kStatSpheresDropped, 1u);
        return;
    }
    spheresStore(slot, s);
    for (uint c = 0u; c < 3u; ++c) {
        sphereAabbsStore(slot * 6u + c, s.centre[c] - s.radius);
        sphereAabbsStore(slot * 6u + 3u + c, s.centre[c] + s.radius);
    }
}

void backwardLaunch(uint launch, uint launchCount) {
    if (launch == 0u) statsAtomicAdd(kStatBackwardLaunches, launchCount);
    // The list holds min(count, capacity) pixels; without indirect dispatch the grid is W x H and
    // launches past the list's length idle.
    if (launch >= min(statsLoad(kStatSpecularPixels), params.sphereCapacity)) return;
    uint pixel = specularPixelsLoad(launch);
    uint2 p = uint2(pixel % camera.frame.x, pixel / camera.frame.x);

    Rng rng = rngCreate(pixel, 0x5eedu, 1u, params.frame);
    PinholeCamera cam = cameraPinhole(camera);
    // The primary ray is re-traced rather than rebuilt from the G-buffer: the G-buffer's normal faces
    // the viewer, and the specular event needs the outward normal to know inside from outside.
    float3 origin = cam.eye;
    // A jittered position inside the pixel: accumulated frames converge to the pixel's mean (what the
    // first-type splat measures), not to the value at its centre (docs/caustics.md).
    float2 pixelPosition = float2(p) + rngNextFloat2(rng);
    // The host's projection jitter shifts the image against the centred pinhole (cameraJitter).
    float2 pinholePosition = pixelPosition - cameraJitter(camera);
    float3 dir = cameraRayDirection(cam, pinholePosition);
    RayDifferential rd = pinholeRayDifferential(cam, pinholePosition);
    float3 throughput = splat3(1.0f);
    float3 sigma = splat3(0.0f);
    float pathLength = 0.0f;
    uint events = 0u;
    bool likelyPath = true;   // every event took its most probable lobe (the filter's guides)
    for (uint vertex = 0u; vertex <= params.maxDepth + 1u; ++vertex) {
        TracePayload hit = traceScene(origin, vertex == 0u ? camera.clip.x : 0.0f, dir, 1.0e30f);
        if (hit.t < 0.0f) break;
        pathLength += hit.t;
        if (dot(sigma, sigma) > 0.0f) throughput *= beerLambert(sigma, hit.t);   // inside an absorbing medium
        SurfaceHit h = sceneSurfaceHit(hit.instance, hit.primitive, hit.barycentrics);
        float3 x = origin + hit.t * dir;
        float3 ng = dot(h.shadingNormal, h.geometricNormal) < 0.0f ? -h.geometricNormal : h.geometricNormal;
        // Transfer onto the triangle's plane (Igehy eq. 12): dP then lies in the surface.
        rd = transferRayDifferential(rd, dir, hit.t, h.geometricNormal);
        if (sceneMaterialIsSpecular(h.material)) {
            if (events >= params.maxDepth) break;
            SpecularEvent ev = sampleSpecularEvent(dir, h.shadingNormal, h.optics, rngNextFloat3(rng), kTransportRadiance);
            if (ev.kind == kEventAbsorbed) break;
            likelyPath = likelyPath && ev.mostLikely;
            if (ev.kind != kEventDiffuse) {
                ++events;
                throughput *= ev.weight;
                float3 dNdx;
                float3 dNdy;
                shadingNormalDerivatives(sceneSurfaceDerivatives(hit.instance, hit.primitive, hit.barycentrics), rd, dNdx, dNdy);
                rd = scatterRayDifferential(rd, dir, ev, h.shadingNormal, dNdx, dNdy, h.optics);
                dir = ev.direction;
                sigma = ev.insideMedium ? volumeSigmaA(h.material.attenuationColor, h.material.attenuationDistance)
                                        : splat3(0.0f);
                origin = x + (dot(dir, ng) > 0.0f ? ng : -ng) * rayEpsilon(x);
                continue;
            }
        }
        // Seen directly. On the specular surface itself (its diffuse lobe) the first-type pass splats into
        // this pixel already. A ray whose jitter crossed the glass's silhouette onto a diffuse surface
        // does not: that pass splats only where the G-buffer (here the glass) shows the receiver. Its
        // sphere gathers the first-type light with throughput 1 (docs/caustics.md, "Glass edges").
        if (events == 0u && sceneMaterialIsSpecular(h.material)) break;
        // Pixel-footprint radius: the differential's footprint parallelogram on the receiver, with the
        // unfolded width (path length x pixel angle) as the reference for the magnification clamps.
        float3 nFacing = dot(h.shadingNormal, dir) < 0.0f ? h.shadingNormal : -h.shadingNormal;
        float radius = params.worldRadius;
        if (params.radiusPolicy == kBackwardRadiusFootprint) {
            GatherRadiusLimits limits;
            limits.scale = params.radiusScale;
            limits.minMagnification = params.minMagnification;
            limits.maxMagnification = params.maxMagnification;
            limits.minRadius = params.minRadius;
            limits.maxRadius = params.maxRadius;
            radius = gatherDiskRadius(rayFootprintArea(rd), pathLength * sqrt(pinholePixelArea(cam)), limits);
        }
        CausticSphere s;
        s.centre = x;
        s.radius = max(clampRadiusAtWalls(x, nFacing, radius), min(params.minRadius, radius));
        s.transmittance = throughput;
        s.objectId = h.objectId;
        s.normal = nFacing;
        s.pixel = pixel;
        s.outgoing = -dir;
        s.likelyPath = likelyPath ? 1u : 0u;
        appendSphere(s);
        return;
    }
}
#endif  // !CAUSTICS_LANG_CPP
#endif  // CAUSTICS_PASS_BACKWARD_H
