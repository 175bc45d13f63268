#ifndef CAUSTICS_COMMON_SPECULAR_LIST_H
#define CAUSTICS_COMMON_SPECULAR_LIST_H
// The second type in list order (docs/caustics.md "Second-type memory"): when the filter runs the second
// type apart, its radiance words, resolved image and guides hold one texel per entry of
// caustics.specularPixels' list instead of one per screen pixel, so their memory follows the specular
// pixels the camera sees, not the screen. The list holds each 8x8 tile's listed pixels in a run, in scan
// order within the tile, and caustics.specularIndex (RGBA32UI, one texel per 8x8 tile, 16 bytes per 64
// pixels) names the run: x its first entry, y and z which of the tile's 64 pixels are listed (bit
// 8 (p.y mod 8) + (p.x mod 8) of y | z << 32). A pixel's entry is x plus the listed pixels before it in
// the tile; kSpecularListNone where it is not listed (not specular, or past the sphere capacity).
// Entry i is texel (i mod 4096, i / 4096) of the list-ordered images: 4096 is the width every Vulkan device
// supports (maxImageDimension2D >= 4096), and a list of one entry per pixel of an 8K view takes 8,100 rows.
#include "common/lang.h"

CAUSTICS_SHARED_BEGIN
CAUSTICS_CONST uint kSpecularListNone = 0xFFFFFFFFu;
CAUSTICS_CONST uint kSpecularListRowShift = 12u;   // log2 of the texels per row
CAUSTICS_CONST uint kSpecularListRow = 4096u;

// Entry `index`'s texel, (-1, -1) for kSpecularListNone.
CAUSTICS_FN int2 specularListTexel(uint index) {
    return index == kSpecularListNone ? int2(-1, -1)
                                      : int2(int(index & (kSpecularListRow - 1u)), int(index >> kSpecularListRowShift));
}
// Rows of the list-ordered images for `entries` list entries (at least one).
CAUSTICS_FN uint specularListRows(uint entries) { return max((entries + kSpecularListRow - 1u) >> kSpecularListRowShift, 1u); }
// Whether a G-buffer texel (its object id and optics, common/scene.h sceneOpticsEncoding) is specular:
// the pixels the list holds (up to the sphere capacity) and the backward pass traces.
CAUSTICS_FN bool gbufferTexelIsSpecular(uint objectId, float4 optics) { return objectId != 0u && optics.w >= 0.5f; }
CAUSTICS_SHARED_END

#if !defined(CAUSTICS_LANG_CPP)
#if defined(CAUSTICS_LANG_HLSL)
#define SPECULAR_BIT_COUNT(v) countbits(v)
#else
#define SPECULAR_BIT_COUNT(v) uint(bitCount(v))
#endif
// Pixel p's list entry from its tile's index texel (above).
uint specularListEntry(uint4 tile, int2 p) {
    uint bit = uint((p.y & 7) * 8 + (p.x & 7));
    uint word = bit < 32u ? tile.y : tile.z;
    uint inWord = bit & 31u;
    if (((word >> inWord) & 1u) == 0u) return kSpecularListNone;
    uint before = SPECULAR_BIT_COUNT(word & ((1u << inWord) - 1u)) + (bit < 32u ? 0u : SPECULAR_BIT_COUNT(tile.y));
    return tile.x + before;
}
// Pixel p's texel in the second type's inputs: p itself (screen layout), or its list entry's texel
// (list order, `listOrder` != 0; (-1, -1): not listed, its inputs are zero). The pass's bindings
// declare specularIndex; include after them.
#define SPECULAR_INPUT_TEXEL(p, listOrder) \
    ((listOrder) != 0u ? specularListTexel(specularListEntry(CAUSTICS_TEXEL(specularIndex, int2((p).x >> 3, (p).y >> 3)), (p))) : (p))
#endif

#endif  // CAUSTICS_COMMON_SPECULAR_LIST_H
