#pragma once
#include <cstdint>

namespace caustics::rhi {

enum class Format : uint32_t {
    Unknown,
    R8_UNORM,
    RG8_UNORM,
    RGBA8_UNORM,
    RGBA8_SRGB,
    BGRA8_UNORM,
    R16_FLOAT,
    RG16_FLOAT,
    RGBA16_FLOAT,
    R32_UINT,
    RG32_UINT,
    RGBA32_UINT,
    R32_FLOAT,
    RG32_FLOAT,
    RGB32_FLOAT,   // vertex/AS-input only
    RGBA32_FLOAT,
    D32_FLOAT,
    D24_UNORM_S8_UINT,
    // Packed HDR colour: DXGI R11G11B10_FLOAT / VK_FORMAT_B10G11R11_UFLOAT_PACK32 (unsigned floats, 6-bit
    // mantissas for red and green, 5 for blue, no alpha) and DXGI R10G10B10A2_UNORM /
    // VK_FORMAT_A2B10G10R10_UNORM_PACK32 (red in the low bits). Added after the others: values are stable.
    R11G11B10_FLOAT,
    RGB10A2_UNORM,
};
// The last enumerator: loops over every format run up to it.
inline constexpr Format kLastFormat = Format::RGB10A2_UNORM;

struct FormatInfo {
    const char* name;
    uint32_t bytesPerPixel;
    bool isDepth;
    bool hasStencil;
    bool isInteger;
};

const FormatInfo& formatInfo(Format format);

}  // namespace caustics::rhi
