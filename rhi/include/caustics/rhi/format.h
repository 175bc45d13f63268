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
};

struct FormatInfo {
    const char* name;
    uint32_t bytesPerPixel;
    bool isDepth;
    bool hasStencil;
    bool isInteger;
};

const FormatInfo& formatInfo(Format format);

}  // namespace caustics::rhi
