#ifndef CAUSTICS_COMMON_MATRIX_H
#define CAUSTICS_COMMON_MATRIX_H
// The one matrix the shared dialect has (docs/shaders.md, "Scene API"): a 4x4 transform stored
// column-major as glm and GLSL store it (the host's glm::mat4 bytes), applied only through
// mat4Mul(m, v) (GLSL m * v) and mat3Mul(m, v) (its upper 3x3 times v). HLSL reads constant buffers
// column-major by default, so mul(m, v) is the same product; a matrix in a raw buffer is read with
// loadFloat4x4.
#include "common/lang.h"

#if defined(CAUSTICS_LANG_CPP)
namespace caustics::shader {
using float4x4 = glm::mat4;
inline float4 mat4Mul(const float4x4& m, float4 v) { return m * v; }
inline float3 mat3Mul(const float4x4& m, float3 v) { return glm::mat3(m) * v; }
}  // namespace caustics::shader
#elif defined(CAUSTICS_LANG_HLSL)
#define mat4Mul(m, v) mul((m), (v))
#define mat3Mul(m, v) mul((float3x3)(m), (v))
// The four columns of a column-major 4x4 (glm's bytes) in a raw buffer: float4x4(...) takes rows.
float4x4 loadFloat4x4(ByteAddressBuffer b, uint offset) {
    return transpose(float4x4(asfloat(b.Load4(offset)), asfloat(b.Load4(offset + 16u)), asfloat(b.Load4(offset + 32u)),
                              asfloat(b.Load4(offset + 48u))));
}
#else
#define float4x4 mat4
#define mat4Mul(m, v) ((m) * (v))
#define mat3Mul(m, v) (mat3(m) * (v))
#endif

#endif  // CAUSTICS_COMMON_MATRIX_H
