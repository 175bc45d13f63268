#ifndef CAUSTICS_PASS_CAUSTIC_RESOLVE_H
#define CAUSTICS_PASS_CAUSTIC_RESOLVE_H
// caustics.resolve in the shared dialect (docs/shaders.md): radiance buffers -> RGBA32F textures, the
// first type, the second type and their sum; or, with one buffer for both types (kResolveCombinedOnly),
// the sum alone. Words: float bits, or fixed point (kResolveFixedPoint: value x scale, invScale =
// 1 / scale, docs/caustics.md "Fixed point") in one uint per channel or, with kResolveWide, one uint64
// per channel (lo, hi words). Entries: resolve.comp, resolve.hlsl.
#include "filter_common.h"

CAUSTICS_SHARED_BEGIN
// Push constants (resolve_bindings.h), 16 bytes.
struct ResolveParams {
    uint width;
    uint height;
    uint flags;       // kResolve*
    float invScale;   // fixed point: 1 / scale
};
CAUSTICS_CONST uint kResolveFixedPoint = 1u;
CAUSTICS_CONST uint kResolveCombinedOnly = 2u;
CAUSTICS_CONST uint kResolveWide = 4u;

// A 64-bit fixed-point word (lo, hi) as a float.
CAUSTICS_FN float resolveWide(uint lo, uint hi) { return float(hi) * 4294967296.0f + float(lo); }
CAUSTICS_SHARED_END

#if !defined(CAUSTICS_LANG_CPP)
#include "bindings/caustic_resolve.h"   // generated from passes/caustic_filter/resolve_bindings.h
#include "common/resources.h"

float3 resolveDecode(uint a, uint b, uint c) {
    if ((params.flags & kResolveFixedPoint) != 0u) return float3(float(a), float(b), float(c)) * params.invScale;
    return float3(filterBitsToFloat(a), filterBitsToFloat(b), filterBitsToFloat(c));
}
// Word i of the first type's buffer, or of the second's.
uint resolveWord(bool second, uint i) { return second ? secondWordsLoad(i) : firstWordsLoad(i); }
float3 resolveRadiance(bool second, uint pixel) {
    if ((params.flags & kResolveWide) != 0u) {
        uint i = 6u * pixel;
        return float3(resolveWide(resolveWord(second, i), resolveWord(second, i + 1u)),
                      resolveWide(resolveWord(second, i + 2u), resolveWord(second, i + 3u)),
                      resolveWide(resolveWord(second, i + 4u), resolveWord(second, i + 5u))) * params.invScale;
    }
    uint i = 3u * pixel;
    return resolveDecode(resolveWord(second, i), resolveWord(second, i + 1u), resolveWord(second, i + 2u));
}

void resolveThread(uint2 p) {
    if (p.x >= params.width || p.y >= params.height) return;
    uint pixel = p.y * params.width + p.x;
    float3 a = resolveRadiance(false, pixel);
    if ((params.flags & kResolveCombinedOnly) != 0u) {
        CAUSTICS_IMAGE_STORE(outCombined, int2(p), float4(a, 1.0f));
        return;
    }
    float3 b = resolveRadiance(true, pixel);
    CAUSTICS_IMAGE_STORE(outFirst, int2(p), float4(a, 1.0f));
    CAUSTICS_IMAGE_STORE(outSecond, int2(p), float4(b, 1.0f));
    CAUSTICS_IMAGE_STORE(outCombined, int2(p), float4(a + b, 1.0f));
}
#endif

#endif  // CAUSTICS_PASS_CAUSTIC_RESOLVE_H
