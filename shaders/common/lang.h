#ifndef CAUSTICS_COMMON_LANG_H
#define CAUSTICS_COMMON_LANG_H
// Portability prelude: the headers in shaders/common are written once and compile as GLSL 4.60
// (glslangValidator, #extension GL_GOOGLE_include_directive), as HLSL (DXC) and as C++20 with GLM.
// Shared code is written in the HLSL spelling (float3, lerp, saturate, mul) with these rules:
//  - float literals carry an `f` suffix (C++: a double would not mix with glm::vec3);
//  - vector splats use splat2/splat3 (HLSL has no float3(x) constructor from one scalar), a float4's
//    first three components toFloat3(v) (C++ GLM has no swizzles);
//  - functions are declared CAUSTICS_FN, out/inout parameters CAUSTICS_OUT(T)/CAUSTICS_INOUT(T),
//    file-scope constants CAUSTICS_CONST;
//  - no matrices in shared code (row/column conventions differ) except float4x4 transforms applied
//    through mat4Mul / mat3Mul (below), no recursion, no pointers;
//  - bit casts are HLSL's asuint(float) / asfloat(uint);
//  - the C++ spelling lives in namespace caustics::shader (CAUSTICS_SHARED_BEGIN/END).
// The HLSL branch is deliberately minimal: Debian 12 has no dxc, so it is not compiled in CI.

#if defined(__cplusplus)
#define CAUSTICS_LANG_CPP 1
#elif defined(__HLSL_VERSION)
#define CAUSTICS_LANG_HLSL 1
#else
#define CAUSTICS_LANG_GLSL 1
#endif

#if defined(CAUSTICS_LANG_CPP)
#include <bit>
#include <cstdint>
#include <glm/glm.hpp>

#define CAUSTICS_SHARED_BEGIN namespace caustics::shader {
#define CAUSTICS_SHARED_END }
#define CAUSTICS_FN inline
#define CAUSTICS_CONST inline constexpr
#define CAUSTICS_OUT(T) T&
#define CAUSTICS_INOUT(T) T&

namespace caustics::shader {
using float2 = glm::vec2;
using float3 = glm::vec3;
using float4 = glm::vec4;
using uint = std::uint32_t;
using uint2 = glm::uvec2;
using uint3 = glm::uvec3;
using uint4 = glm::uvec4;
using int2 = glm::ivec2;
using int3 = glm::ivec3;

using glm::abs;
using glm::acos;
using glm::atan;
using glm::ceil;
using glm::clamp;
using glm::cos;
using glm::cross;
using glm::dot;
using glm::exp;
using glm::floor;
using glm::length;
using glm::log;
using glm::max;
using glm::min;
using glm::normalize;
using glm::pow;
using glm::reflect;
using glm::round;
using glm::sin;
using glm::sqrt;
using glm::tan;

inline float atan2(float y, float x) { return glm::atan(y, x); }
inline float saturate(float x) { return glm::clamp(x, 0.0f, 1.0f); }
inline float3 saturate(float3 x) { return glm::clamp(x, 0.0f, 1.0f); }
inline float lerp(float a, float b, float t) { return glm::mix(a, b, t); }
inline float3 lerp(float3 a, float3 b, float t) { return glm::mix(a, b, t); }
inline float2 splat2(float x) { return float2(x); }
inline float3 splat3(float x) { return float3(x); }
inline float3 toFloat3(float4 v) { return float3(v); }
// HLSL's bit casts of one 32-bit scalar (GLSL floatBitsToUint / uintBitsToFloat).
inline uint asuint(float x) { return std::bit_cast<uint>(x); }
inline float asfloat(uint x) { return std::bit_cast<float>(x); }
}  // namespace caustics::shader

#elif defined(CAUSTICS_LANG_HLSL)
#define CAUSTICS_SHARED_BEGIN
#define CAUSTICS_SHARED_END
#define CAUSTICS_FN
#define CAUSTICS_CONST static const
#define CAUSTICS_OUT(T) out T
#define CAUSTICS_INOUT(T) inout T
#define splat2(x) ((float2)(x))
#define splat3(x) ((float3)(x))
#define toFloat3(v) ((v).xyz)
// lerp, saturate, mul, atan2 are HLSL intrinsics.

#else  // GLSL
#define CAUSTICS_SHARED_BEGIN
#define CAUSTICS_SHARED_END
#define CAUSTICS_FN
#define CAUSTICS_CONST const
#define CAUSTICS_OUT(T) out T
#define CAUSTICS_INOUT(T) inout T
#define float2 vec2
#define float3 vec3
#define float4 vec4
#define uint2 uvec2
#define uint3 uvec3
#define uint4 uvec4
#define int2 ivec2
#define int3 ivec3
#define splat2(x) vec2(x)
#define splat3(x) vec3(x)
#define toFloat3(v) ((v).xyz)
#define lerp(a, b, t) mix(a, b, t)
#define saturate(x) clamp(x, 0.0f, 1.0f)
#define mul(m, v) ((m) * (v))
#define atan2(y, x) atan(y, x)
#define asuint(x) floatBitsToUint(x)
#define asfloat(x) uintBitsToFloat(x)
#endif

CAUSTICS_SHARED_BEGIN
CAUSTICS_CONST float kPi = 3.14159265358979f;
CAUSTICS_CONST float kTwoPi = 6.28318530717959f;
CAUSTICS_CONST float kInvPi = 0.318309886183791f;
CAUSTICS_SHARED_END

// The one matrix of the dialect: a 4x4 transform stored column-major as glm and GLSL store it (the
// host's glm::mat4 bytes), applied only through mat4Mul(m, v) (GLSL m * v) and mat3Mul(m, v) (its
// upper 3x3 times v). HLSL reads constant buffers column-major by default, so mul(m, v) is the same
// product; a matrix in a raw buffer is read with loadFloat4x4.
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


// GLSL's packUnorm2x16 / unpackUnorm2x16 / packSnorm2x16 / unpackSnorm2x16: built in for GLSL and
// GLM (C++), spelled out for HLSL (round(clamp(v) x 65535 or 32767), the snorm halves two's
// complement; GLSL 4.60 section 8.4).
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


#endif  // CAUSTICS_COMMON_LANG_H
