#ifndef CAUSTICS_PASS_BACKWARD_H
#define CAUSTICS_PASS_BACKWARD_H
// caustics.backward in the shared dialect (paper 3.3, Figure 5; docs/shaders.md): one launch per entry
// of caustics.specularPixels' list, a camera pixel whose G-buffer surface is specular. The launch traces
// through the specular chain (radiance transport) to the first diffuse hit; that hit becomes an
// integration sphere, appended with its AABB in the sphere BLAS at the next slot of a counter. The
// launch follows each event's most probable lobe and may start one more branch along the others
// (kBackwardMaxSpheres spheres; docs/caustics.md "Second-type lobes"). Slots at
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
// Push constants (backward_bindings.h), 48 bytes.
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
    uint maxSpheres;          // branches (spheres) a launch may have: 1 or kBackwardMaxSpheres (lobe splitting)
    uint pad0;
};
// The most spheres one backward launch appends (docs/caustics.md "Second-type lobes"): the sphere
// capacity allows this many per pixel (caustics/sphere_capacity.h).
CAUSTICS_CONST uint kBackwardMaxSpheres = 2u;
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

// One camera path through the specular chain: where its next ray starts and what it carries.
struct BackwardBranch {
    float3 origin;
    float3 dir;
    RayDifferential rd;
    float3 throughput;
    float3 sigma;       // absorption inside the medium the ray runs in (0 outside)
    float pathLength;
    uint events;
    bool likelyPath;    // every event took its most probable lobe (the filter's guides)
    bool primary;       // the camera ray itself: starts at the near plane
};

// The branch's integration sphere at its diffuse hit x (surface h) for pixel `pixel`. Pixel-footprint
// radius: the differential's footprint parallelogram on the receiver, with the unfolded width (path
// length x pixel angle) as the reference for the magnification clamps.
void appendBranchSphere(BackwardBranch b, SurfaceHit h, float3 x, uint pixel, PinholeCamera cam) {
    float3 nFacing = dot(h.shadingNormal, b.dir) < 0.0f ? h.shadingNormal : -h.shadingNormal;
    float radius = params.worldRadius;
    if (params.radiusPolicy == kBackwardRadiusFootprint) {
        GatherRadiusLimits limits;
        limits.scale = params.radiusScale;
        limits.minMagnification = params.minMagnification;
        limits.maxMagnification = params.maxMagnification;
        limits.minRadius = params.minRadius;
        limits.maxRadius = params.maxRadius;
        radius = gatherDiskRadius(rayFootprintArea(b.rd), rayFootprintMajorAxis(b.rd), b.pathLength * sqrt(pinholePixelArea(cam)), limits);
    }
    CausticSphere s;
    s.centre = x;
    s.radius = max(clampRadiusAtWalls(x, nFacing, radius), min(params.minRadius, radius));
    s.transmittance = b.throughput;
    s.objectId = h.objectId;
    s.normal = nFacing;
    s.pixel = pixel;
    s.outgoing = -b.dir;
    s.likelyPath = b.likelyPath ? 1u : 0u;
    appendSphere(s);
}

// Scatters branch b at a specular surface (h, hit at x, outward-side geometric normal ng) into event ev.
void backwardScatter(CAUSTICS_INOUT(BackwardBranch) b, SpecularEvent ev, SurfaceHit h, TracePayload hit, float3 x, float3 ng,
                     float3 throughputScale) {
    ++b.events;
    b.throughput *= ev.weight * throughputScale;
    b.likelyPath = b.likelyPath && ev.mostLikely;
    float3 dNdx;
    float3 dNdy;
    shadingNormalDerivatives(sceneSurfaceDerivatives(hit.instance, hit.primitive, hit.barycentrics), b.rd, dNdx, dNdy);
    b.rd = scatterRayDifferential(b.rd, b.dir, ev, h.shadingNormal, dNdx, dNdy, h.optics);
    b.dir = ev.direction;
    b.sigma = ev.insideMedium ? volumeSigmaA(h.material.attenuationColor, h.material.attenuationDistance) : splat3(0.0f);
    b.origin = x + (dot(b.dir, ng) > 0.0f ? ng : -ng) * rayEpsilon(x);
    b.primary = false;
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
    // A jittered position inside the pixel: accumulated frames converge to the pixel's mean (what the
    // first-type splat measures), not to the value at its centre (docs/caustics.md).
    float2 pixelPosition = float2(p) + rngNextFloat2(rng);
    // The host's projection jitter shifts the image against the centred pinhole (cameraJitter).
    float2 pinholePosition = pixelPosition - cameraJitter(camera);
    BackwardBranch b;
    b.origin = cam.eye;
    b.dir = cameraRayDirection(cam, pinholePosition);
    b.rd = pinholeRayDifferential(cam, pinholePosition);
    b.throughput = splat3(1.0f);
    b.sigma = splat3(0.0f);
    b.pathLength = 0.0f;
    b.events = 0u;
    b.likelyPath = true;
    b.primary = true;
    // Lobe splitting (docs/caustics.md "Second-type lobes"): while the launch may still add a branch,
    // an event follows its most probable lobe with that probability as weight, and with the other lobes'
    // probability it also starts a second branch along one of them (picked in proportion, weight as
    // sampled). Once the launch holds params.maxSpheres branches, events pick one lobe as the paper does.
    uint branches = 1u;
    bool hasPending = false;
    BackwardBranch pending = b;   // read only after a spawn wrote it; initialised for the compilers' flow checks
    for (uint guard = 0u; guard < 2u * (params.maxDepth + 2u); ++guard) {
        bool ended = true;
        TracePayload hit = traceScene(b.origin, b.primary ? camera.clip.x : 0.0f, b.dir, 1.0e30f);
        if (hit.t >= 0.0f) {
            ended = false;
            b.pathLength += hit.t;
            if (dot(b.sigma, b.sigma) > 0.0f) b.throughput *= beerLambert(b.sigma, hit.t);   // inside an absorbing medium
            SurfaceHit h = sceneSurfaceHit(hit.instance, hit.primitive, hit.barycentrics);
            float3 x = b.origin + hit.t * b.dir;
            float3 ng = dot(h.shadingNormal, h.geometricNormal) < 0.0f ? -h.geometricNormal : h.geometricNormal;
            // Transfer onto the triangle's plane (Igehy eq. 12): dP then lies in the surface.
            b.rd = transferRayDifferential(b.rd, b.dir, hit.t, h.geometricNormal);
            bool sphere = true;
            if (sceneMaterialIsSpecular(h.material)) {
                sphere = false;
                ended = b.events >= params.maxDepth;
                if (!ended) {
                    float3 u = rngNextFloat3(rng);
                    // The facet (microfacet, Fresnel) once: the lobe chances and both branches' events share it.
                    SpecularFacet facet = specularFacet(b.dir, h.shadingNormal, h.optics, float2(u.x, u.y));
                    SpecularLobeChances c = specularLobeChancesAt(facet, h.optics);
                    uint most = specularMostLikelyLobe(c);
                    float pMost = specularLobeInterval(c, most).y;
                    float pick = u.z;
                    float3 scale = splat3(1.0f);
                    if (branches < params.maxSpheres && pMost > 0.0f) {
                        if (u.z < 1.0f - pMost) {
                            // The second branch, along a lobe other than the most probable one.
                            SpecularEvent other = sampleSpecularEventOnFacet(facet, b.dir, h.optics, specularLobePickOutside(c, most, u.z),
                                                                             kTransportRadiance);
                            if (other.kind == kEventReflect || other.kind == kEventRefract) {
                                pending = b;
                                backwardScatter(pending, other, h, hit, x, ng, splat3(1.0f));
                                hasPending = true;
                                ++branches;
                            } else if (other.kind == kEventDiffuse && b.events > 0u) {
                                // The diffuse base: that branch ends on this specular surface, its sphere
                                // here, as a sampled event's would (at the first event the first type has it).
                                BackwardBranch onSurface = b;
                                onSurface.throughput *= other.weight;
                                onSurface.likelyPath = false;
                                appendBranchSphere(onSurface, h, x, pixel, cam);
                                ++branches;
                            }
                        }
                        pick = specularLobePickCentre(c, most);
                        scale = splat3(pMost);
                    }
                    SpecularEvent ev = sampleSpecularEventOnFacet(facet, b.dir, h.optics, pick, kTransportRadiance);
                    if (ev.kind == kEventAbsorbed) ended = true;
                    else if (ev.kind != kEventDiffuse) backwardScatter(b, ev, h, hit, x, ng, scale);
                    else {
                        b.throughput *= ev.weight * scale;   // the diffuse base: 1 / its chance (common/specular_event.h)
                        b.likelyPath = b.likelyPath && ev.mostLikely;
                        sphere = true;
                    }
                }
            }
            // Seen directly. On the specular surface itself (its diffuse lobe) the first-type pass splats into
            // this pixel already. A ray whose jitter crossed the glass's silhouette onto a diffuse surface
            // does not: that pass splats only where the G-buffer (here the glass) shows the receiver. Its
            // sphere gathers the first-type light with throughput 1 (docs/caustics.md, "Glass edges").
            if (sphere && !ended) {
                ended = true;
                if (!(b.events == 0u && sceneMaterialIsSpecular(h.material))) appendBranchSphere(b, h, x, pixel, cam);
            }
        }
        if (!ended) continue;
        if (!hasPending) return;
        b = pending;
        hasPending = false;
    }
}
#endif  // !CAUSTICS_LANG_CPP
#endif  // CAUSTICS_PASS_BACKWARD_H
