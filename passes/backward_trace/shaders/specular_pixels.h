#ifndef CAUSTICS_PASS_SPECULAR_PIXELS_H
#define CAUSTICS_PASS_SPECULAR_PIXELS_H
// caustics.specularPixels in the shared dialect (docs/shaders.md): the camera pixels whose G-buffer
// surface is specular (objectId != 0 and optics.w >= 0.5), compacted into a list of pixel indices cut
// at the sphere capacity, and the grid (count, 1, 1) of the backward pass's indirect dispatch.
// caustics.backward then launches once per specular pixel instead of once per pixel
// (docs/caustics.md, "Second-type cost"). Thread (0, 0) also records the sphere capacity the frame was
// built with (kStatSphereCapacity), for the host's statistics and the gather's intersection shader.
// Entries: specular_pixels.comp, specular_pixels.hlsl.
#include "common/caustic_stats.h"
#include "common/lang.h"

CAUSTICS_SHARED_BEGIN
// Push constants (specular_pixels_bindings.h), 12 bytes.
struct SpecularPixelParams {
    uint width;
    uint height;
    uint sphereCapacity;   // list entries: one sphere slot each (caustics/sphere_capacity.h)
};
// Whether a G-buffer texel (its object id and optics, common/scene.h sceneOpticsEncoding) is specular.
CAUSTICS_FN bool gbufferTexelIsSpecular(uint objectId, float4 optics) { return objectId != 0u && optics.w >= 0.5f; }
CAUSTICS_SHARED_END

#if !defined(CAUSTICS_LANG_CPP)
#include "bindings/specular_pixels.h"   // generated from passes/backward_trace/specular_pixels_bindings.h
#include "common/resources.h"

void specularPixelsThread(uint2 p) {
    if (p.x == 0u && p.y == 0u) statsStore(kStatSphereCapacity, params.sphereCapacity);
    if (p.x >= params.width || p.y >= params.height) return;
    if (!gbufferTexelIsSpecular(CAUSTICS_TEXEL_UINT(gObjectId, int2(p)), CAUSTICS_TEXEL(gOptics, int2(p)))) return;
    // Every specular pixel is counted (it sizes the next frame's capacity), only those below the
    // capacity are listed: past it there is no sphere slot.
    uint slot = statsAtomicAdd(kStatSpecularPixels, 1u);
    if (slot >= params.sphereCapacity) return;
    specularPixelsStore(slot, p.y * params.width + p.x);
    argsAtomicAdd(0u, 1u);
}
#endif  // !CAUSTICS_LANG_CPP
#endif  // CAUSTICS_PASS_SPECULAR_PIXELS_H
