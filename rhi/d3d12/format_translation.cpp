#include "format_translation.h"

namespace caustics::rhi::d3d12 {

DXGI_FORMAT toDxgiFormat(Format format) {
    switch (format) {
        case Format::Unknown: return DXGI_FORMAT_UNKNOWN;
        case Format::R8_UNORM: return DXGI_FORMAT_R8_UNORM;
        case Format::RG8_UNORM: return DXGI_FORMAT_R8G8_UNORM;
        case Format::RGBA8_UNORM: return DXGI_FORMAT_R8G8B8A8_UNORM;
        case Format::RGBA8_SRGB: return DXGI_FORMAT_R8G8B8A8_UNORM_SRGB;
        case Format::BGRA8_UNORM: return DXGI_FORMAT_B8G8R8A8_UNORM;
        case Format::R16_FLOAT: return DXGI_FORMAT_R16_FLOAT;
        case Format::RG16_FLOAT: return DXGI_FORMAT_R16G16_FLOAT;
        case Format::RGBA16_FLOAT: return DXGI_FORMAT_R16G16B16A16_FLOAT;
        case Format::R32_UINT: return DXGI_FORMAT_R32_UINT;
        case Format::RG32_UINT: return DXGI_FORMAT_R32G32_UINT;
        case Format::RGBA32_UINT: return DXGI_FORMAT_R32G32B32A32_UINT;
        case Format::R32_FLOAT: return DXGI_FORMAT_R32_FLOAT;
        case Format::RG32_FLOAT: return DXGI_FORMAT_R32G32_FLOAT;
        case Format::RGB32_FLOAT: return DXGI_FORMAT_R32G32B32_FLOAT;
        case Format::RGBA32_FLOAT: return DXGI_FORMAT_R32G32B32A32_FLOAT;
        case Format::D32_FLOAT: return DXGI_FORMAT_D32_FLOAT;
        case Format::D24_UNORM_S8_UINT: return DXGI_FORMAT_D24_UNORM_S8_UINT;
        case Format::R11G11B10_FLOAT: return DXGI_FORMAT_R11G11B10_FLOAT;
        case Format::RGB10A2_UNORM: return DXGI_FORMAT_R10G10B10A2_UNORM;
    }
    return DXGI_FORMAT_UNKNOWN;
}

DXGI_FORMAT toDxgiResourceFormat(Format format) {
    switch (format) {
        case Format::D32_FLOAT: return DXGI_FORMAT_R32_TYPELESS;
        case Format::D24_UNORM_S8_UINT: return DXGI_FORMAT_R24G8_TYPELESS;
        default: return toDxgiFormat(format);
    }
}

DXGI_FORMAT toDxgiSrvFormat(Format format) {
    switch (format) {
        case Format::D32_FLOAT: return DXGI_FORMAT_R32_FLOAT;
        case Format::D24_UNORM_S8_UINT: return DXGI_FORMAT_R24_UNORM_X8_TYPELESS;
        default: return toDxgiFormat(format);
    }
}

DXGI_FORMAT toDxgiDsvFormat(Format format) {
    switch (format) {
        case Format::D32_FLOAT: return DXGI_FORMAT_D32_FLOAT;
        case Format::D24_UNORM_S8_UINT: return DXGI_FORMAT_D24_UNORM_S8_UINT;
        default: return DXGI_FORMAT_UNKNOWN;
    }
}

}  // namespace caustics::rhi::d3d12
