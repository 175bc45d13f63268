#include "caustics/rhi/format.h"
#include "vk_texture.h"

namespace caustics::rhi::vulkan {

VkFormat toVkFormat(Format format) {
    switch (format) {
        case Format::Unknown: return VK_FORMAT_UNDEFINED;
        case Format::R8_UNORM: return VK_FORMAT_R8_UNORM;
        case Format::RG8_UNORM: return VK_FORMAT_R8G8_UNORM;
        case Format::RGBA8_UNORM: return VK_FORMAT_R8G8B8A8_UNORM;
        case Format::RGBA8_SRGB: return VK_FORMAT_R8G8B8A8_SRGB;
        case Format::BGRA8_UNORM: return VK_FORMAT_B8G8R8A8_UNORM;
        case Format::R16_FLOAT: return VK_FORMAT_R16_SFLOAT;
        case Format::RG16_FLOAT: return VK_FORMAT_R16G16_SFLOAT;
        case Format::RGBA16_FLOAT: return VK_FORMAT_R16G16B16A16_SFLOAT;
        case Format::R32_UINT: return VK_FORMAT_R32_UINT;
        case Format::RG32_UINT: return VK_FORMAT_R32G32_UINT;
        case Format::RGBA32_UINT: return VK_FORMAT_R32G32B32A32_UINT;
        case Format::R32_FLOAT: return VK_FORMAT_R32_SFLOAT;
        case Format::RG32_FLOAT: return VK_FORMAT_R32G32_SFLOAT;
        case Format::RGB32_FLOAT: return VK_FORMAT_R32G32B32_SFLOAT;
        case Format::RGBA32_FLOAT: return VK_FORMAT_R32G32B32A32_SFLOAT;
        case Format::D32_FLOAT: return VK_FORMAT_D32_SFLOAT;
        case Format::D24_UNORM_S8_UINT: return VK_FORMAT_D24_UNORM_S8_UINT;
        case Format::R11G11B10_FLOAT: return VK_FORMAT_B10G11R11_UFLOAT_PACK32;
        case Format::RGB10A2_UNORM: return VK_FORMAT_A2B10G10R10_UNORM_PACK32;
    }
    return VK_FORMAT_UNDEFINED;
}

VkImageAspectFlags aspectOf(Format format) {
    const FormatInfo& info = formatInfo(format);
    if (info.hasStencil) return VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
    if (info.isDepth) return VK_IMAGE_ASPECT_DEPTH_BIT;
    return VK_IMAGE_ASPECT_COLOR_BIT;
}

}  // namespace caustics::rhi::vulkan
