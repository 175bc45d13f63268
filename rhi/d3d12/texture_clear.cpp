#include "texture_clear.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

namespace caustics::rhi::d3d12 {

ClearMethod chooseClearMethod(const TextureDesc& desc, bool uintValues) {
    const FormatInfo& info = formatInfo(desc.format);
    if (info.isDepth) return hasAny(desc.usage, TextureUsage::DepthStencil) && !uintValues ? ClearMethod::DepthStencil
                                                                                           : ClearMethod::Copy;
    // UAV clears convert values to the view format: floats on float/unorm views, uints on integer views.
    if (hasAny(desc.usage, TextureUsage::Storage) && uintValues == info.isInteger)
        return uintValues ? ClearMethod::UavUint : ClearMethod::UavFloat;
    if (hasAny(desc.usage, TextureUsage::RenderTarget) && !uintValues && !info.isInteger) return ClearMethod::RenderTarget;
    return ClearMethod::Copy;
}

uint16_t floatToHalf(float value) {
    const uint32_t f = std::bit_cast<uint32_t>(value);
    const uint32_t sign = (f >> 16) & 0x8000u;
    const uint32_t absBits = f & 0x7FFFFFFFu;
    if (absBits >= 0x7F800000u) return uint16_t(sign | 0x7C00u | (absBits > 0x7F800000u ? 0x200u : 0u));  // inf/NaN
    if (absBits >= 0x477FF000u) return uint16_t(sign | 0x7C00u);   // rounds beyond 65504: inf
    if (absBits < 0x38800000u) {   // below the smallest normal half (2^-14): subnormal or zero
        const float a = std::bit_cast<float>(absBits);
        return uint16_t(sign | uint32_t(std::nearbyint(a * 16777216.0f)));   // units of 2^-24
    }
    // Normal: rebias the exponent (127 -> 15), round the 23-bit mantissa to 10 bits, ties to even.
    const uint32_t rebased = absBits - ((127u - 15u) << 23);
    const uint32_t lsb = (rebased >> 13) & 1u;
    return uint16_t(sign | ((rebased + 0xFFFu + lsb) >> 13));
}

namespace {

uint8_t unorm8(float v) { return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }
float srgbEncode(float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}
template <typename T>
void append(std::vector<uint8_t>& out, T v) {
    const size_t at = out.size();
    out.resize(at + sizeof(T));
    std::memcpy(out.data() + at, &v, sizeof(T));
}
uint32_t channelsOf(Format f) {
    switch (f) {
        case Format::R8_UNORM: case Format::R16_FLOAT: case Format::R32_UINT: case Format::R32_FLOAT:
        case Format::D32_FLOAT: case Format::D24_UNORM_S8_UINT: return 1;
        case Format::RG8_UNORM: case Format::RG16_FLOAT: case Format::RG32_UINT: case Format::RG32_FLOAT: return 2;
        case Format::RGB32_FLOAT: case Format::R11G11B10_FLOAT: return 3;
        case Format::Unknown: return 0;
        default: return 4;
    }
}

// An unsigned small float of `mantissaBits` (6: 11-bit, 5: 10-bit) with the half's 5-bit exponent:
// the half's bits shifted down, rounded to nearest (negatives clamp to 0).
uint32_t smallFloat(float v, uint32_t mantissaBits) {
    const uint32_t drop = 10u - mantissaBits;
    const uint32_t h = floatToHalf(std::max(v, 0.0f)) & 0x7FFFu;
    if (h >= 0x7C00u) return (0x1Fu << mantissaBits) | (h > 0x7C00u ? 1u : 0u);   // inf, NaN
    return std::min((h + (1u << (drop - 1))) >> drop, (0x1Fu << mantissaBits) - 1u);   // never rounds into inf
}
uint32_t unormBits(float v, uint32_t max) { return uint32_t(std::lround(std::clamp(v, 0.0f, 1.0f) * float(max))); }

}  // namespace

std::vector<uint8_t> encodeClearPixel(Format format, const float v[4]) {
    std::vector<uint8_t> out;
    const uint32_t n = channelsOf(format);
    switch (format) {
        case Format::R8_UNORM: case Format::RG8_UNORM: case Format::RGBA8_UNORM:
            for (uint32_t c = 0; c < n; ++c) out.push_back(unorm8(v[c]));
            break;
        case Format::RGBA8_SRGB:
            for (uint32_t c = 0; c < 3; ++c) out.push_back(unorm8(srgbEncode(v[c])));
            out.push_back(unorm8(v[3]));   // alpha is linear
            break;
        case Format::BGRA8_UNORM:
            for (uint32_t c : {2u, 1u, 0u, 3u}) out.push_back(unorm8(v[c]));
            break;
        case Format::R16_FLOAT: case Format::RG16_FLOAT: case Format::RGBA16_FLOAT:
            for (uint32_t c = 0; c < n; ++c) append(out, floatToHalf(v[c]));
            break;
        case Format::R11G11B10_FLOAT:   // red in bits 0-10, green 11-21, blue 22-31
            append(out, smallFloat(v[0], 6) | smallFloat(v[1], 6) << 11 | smallFloat(v[2], 5) << 22);
            break;
        case Format::RGB10A2_UNORM:   // red in bits 0-9, green 10-19, blue 20-29, alpha 30-31
            append(out, unormBits(v[0], 1023) | unormBits(v[1], 1023) << 10 | unormBits(v[2], 1023) << 20 |
                            unormBits(v[3], 3) << 30);
            break;
        case Format::D24_UNORM_S8_UINT:   // 24-bit depth in the low bits, stencil 0 in the top byte
            append(out, uint32_t(std::lround(double(std::clamp(v[0], 0.0f, 1.0f)) * 16777215.0)));
            break;
        default:   // 32-bit channels: floats as floats, integer formats as the floats' bit patterns
            for (uint32_t c = 0; c < n; ++c) append(out, v[c]);
            break;
    }
    return out;
}

std::vector<uint8_t> encodeClearPixel(Format format, const uint32_t v[4]) {
    const FormatInfo& info = formatInfo(format);
    std::vector<uint8_t> out;
    if (info.isInteger) {
        for (uint32_t c = 0; c < channelsOf(format); ++c) append(out, v[c]);
        return out;
    }
    float asFloat[4];
    for (int c = 0; c < 4; ++c) asFloat[c] = std::bit_cast<float>(v[c]);
    return encodeClearPixel(format, asFloat);
}

}  // namespace caustics::rhi::d3d12
