#ifndef CAUSTICS_COMMON_PACKING_H
#define CAUSTICS_COMMON_PACKING_H
// GLSL's packUnorm2x16 / unpackUnorm2x16 / packSnorm2x16 / unpackSnorm2x16 in the shared dialect:
// built in for GLSL and GLM (C++), spelled out for HLSL (round(clamp(v) x 65535 or 32767), the
// snorm halves two's complement; GLSL 4.60 section 8.4).
#include "common/lang.h"

#if defined(CAUSTICS_LANG_CPP)
namespace caustics::shader {
using glm::packSnorm2x16;
using glm::packUnorm2x16;
using glm::unpackSnorm2x16;
using glm::unpackUnorm2x16;
}  // namespace caustics::shader
#elif defined(CAUSTICS_LANG_HLSL)
uint packUnorm2x16(float2 v) {
    uint2 q = uint2(round(saturate(v) * 65535.0f));
    return q.x | (q.y << 16);
}
float2 unpackUnorm2x16(uint p) { return float2(p & 0xFFFFu, p >> 16) / 65535.0f; }
uint packSnorm2x16(float2 v) {
    int2 q = int2(round(clamp(v, -1.0f, 1.0f) * 32767.0f));
    return (uint(q.x) & 0xFFFFu) | (uint(q.y) << 16);
}
float2 unpackSnorm2x16(uint p) {
    int2 q = int2(int(p << 16) >> 16, int(p) >> 16);
    return clamp(float2(q) / 32767.0f, -1.0f, 1.0f);
}
#endif

#endif  // CAUSTICS_COMMON_PACKING_H
