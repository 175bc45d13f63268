#ifndef CAUSTICS_PASS_SPECULAR_PIXELS_H
#define CAUSTICS_PASS_SPECULAR_PIXELS_H
// caustics.specularPixels in the shared dialect (docs/shaders.md): the camera pixels whose G-buffer
// surface is specular (objectId != 0 and optics.w >= 0.5), compacted into a list of pixel indices cut
// at the sphere capacity (one run per 8x8 tile; common/specular_list.h), and the grid (count, 1, 1) of
// the backward pass's indirect dispatch.
// caustics.backward then launches once per specular pixel instead of once per pixel
// (docs/caustics.md, "Second-type cost"). Thread (0, 0) also records the sphere capacity the frame was
// built with (kStatSphereCapacity), for the host's statistics and the gather's intersection shader.
// Entries: specular_pixels.comp, specular_pixels.hlsl.
#include "common/caustic_stats.h"
#include "common/lang.h"
#include "common/specular_list.h"

CAUSTICS_SHARED_BEGIN
// Push constants (specular_pixels_bindings.h), 16 bytes.
struct SpecularPixelParams {
    uint width;
    uint height;
    uint sphereCapacity;   // list entries: one sphere slot each (caustics/sphere_capacity.h)
    uint writeIndex;       // 1: every pixel's entry into specularIndex (the second type in list order)
};
CAUSTICS_SHARED_END

#if !defined(CAUSTICS_LANG_CPP)
#include "bindings/specular_pixels.h"   // generated from passes/backward_trace/specular_pixels_bindings.h
#include "common/group_shared.h"
#include "common/resources.h"

// The group's 8x8 tile: which pixels are specular, which of them are listed (bits as in
// common/specular_list.h), and the tile's first list entry.
CAUSTICS_GROUPSHARED uint sSpecular[2];
CAUSTICS_GROUPSHARED uint sListed[2];
CAUSTICS_GROUPSHARED uint sFirstEntry;

// One 8x8 group per tile; `local` = 8 (p.y mod 8) + (p.x mod 8). The tile's specular pixels take one run
// of the list (one atomic add per tile), in scan order within the tile: each pixel's entry follows from
// the tile's index texel (common/specular_list.h).
void specularPixelsThread(uint2 p, uint2 tile, uint local) {
    if (p.x == 0u && p.y == 0u) statsStore(kStatSphereCapacity, params.sphereCapacity);
    if (local < 2u) {
        sSpecular[local] = 0u;
        sListed[local] = 0u;
    }
    CAUSTICS_GROUP_BARRIER();
    bool specular = p.x < params.width && p.y < params.height &&
                    gbufferTexelIsSpecular(CAUSTICS_TEXEL_UINT(gObjectId, int2(p)), CAUSTICS_TEXEL(gOptics, int2(p)));
    uint word = local >> 5, bit = 1u << (local & 31u);
    if (specular) CAUSTICS_GROUP_ATOMIC_OR(sSpecular[word], bit);
    CAUSTICS_GROUP_BARRIER();
    // Every specular pixel is counted (it sizes the next frame's capacity), only those below the
    // capacity are listed: past it there is no sphere slot.
    if (local == 0u) {
        uint count = SPECULAR_BIT_COUNT(sSpecular[0]) + SPECULAR_BIT_COUNT(sSpecular[1]);
        sFirstEntry = count != 0u ? statsAtomicAdd(kStatSpecularPixels, count) : 0u;
    }
    CAUSTICS_GROUP_BARRIER();
    if (specular) {
        uint entry = sFirstEntry + SPECULAR_BIT_COUNT(sSpecular[word] & (bit - 1u)) + (word != 0u ? SPECULAR_BIT_COUNT(sSpecular[0]) : 0u);
        if (entry < params.sphereCapacity) {
            specularPixelsStore(entry, p.y * params.width + p.x);
            argsAtomicAdd(0u, 1u);
            CAUSTICS_GROUP_ATOMIC_OR(sListed[word], bit);
        }
    }
    if (params.writeIndex == 0u) return;
    CAUSTICS_GROUP_BARRIER();
    if (local == 0u) CAUSTICS_IMAGE_STORE(specularIndex, int2(tile), uint4(sFirstEntry, sListed[0], sListed[1], 0u));
}
#endif  // !CAUSTICS_LANG_CPP
#endif  // CAUSTICS_PASS_SPECULAR_PIXELS_H
