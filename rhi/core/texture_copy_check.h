#pragma once
// Validation of ICommandList::copyTexture regions, shared by both backends (device-free): the
// rectangle must lie inside the source mip and, moved to the destination offset, inside the
// destination mip; both formats must have the same bytes per texel (Vulkan "size-compatible"
// formats, vkCmdCopyImage VUIDs; D3D12 CopyTextureRegion needs the same format family).
#include <cstdint>

#include "caustics/rhi/command_list.h"
#include "caustics/rhi/result.h"

namespace caustics::rhi {

struct TextureCopyExtent {
    uint32_t width = 0, height = 0;
};

Result<TextureCopyExtent> checkTextureCopy(const TextureDesc& dst, const TextureRegion& dstRegion,
                                           const TextureDesc& src, const TextureRegion& srcRegion);

}  // namespace caustics::rhi
