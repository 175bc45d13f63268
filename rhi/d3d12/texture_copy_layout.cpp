#include "texture_copy_layout.h"

#include <algorithm>
#include <cstring>

#include "caustics/rhi/shader_table_layout.h"   // alignUp

namespace caustics::rhi::d3d12 {

Result<TextureCopyLayout> textureCopyLayout(const TextureDesc& desc, uint32_t layer, uint32_t mip) {
    if (mip >= desc.mipLevels || layer >= desc.arrayLayers)
        return makeError("d3d12 texture copy: '" + desc.debugName + "' has no mip " + std::to_string(mip) +
                         " / layer " + std::to_string(layer));
    const uint32_t bpp = formatInfo(desc.format).bytesPerPixel;
    if (bpp == 0) return makeError("d3d12 texture copy: '" + desc.debugName + "' has a format without a size");
    TextureCopyLayout l;
    l.width = std::max(1u, desc.width >> mip);
    l.height = std::max(1u, desc.height >> mip);
    // D3D12CalcSubresource: MipSlice + ArraySlice * MipLevels (+ PlaneSlice * MipLevels * ArraySize, plane 0).
    l.subresource = mip + layer * desc.mipLevels;
    l.tightRowBytes = uint64_t(l.width) * bpp;
    l.tightBytes = l.tightRowBytes * l.height;
    l.rowPitch = alignUp(l.tightRowBytes, kTexturePitchAlignment);
    l.stagingBytes = l.rowPitch * l.height;
    return l;
}

bool copyNeedsNoRepack(const TextureCopyLayout& layout, uint64_t bufferOffset) {
    return layout.rowPitch == layout.tightRowBytes && bufferOffset % kTexturePlacementAlignment == 0;
}

void packRowsToPitch(const TextureCopyLayout& layout, std::span<const uint8_t> tight, std::span<uint8_t> pitched) {
    for (uint32_t row = 0; row < layout.height; ++row)
        std::memcpy(pitched.data() + row * layout.rowPitch, tight.data() + row * layout.tightRowBytes,
                    layout.tightRowBytes);
}

void unpackRowsFromPitch(const TextureCopyLayout& layout, std::span<const uint8_t> pitched, std::span<uint8_t> tight) {
    for (uint32_t row = 0; row < layout.height; ++row)
        std::memcpy(tight.data() + row * layout.tightRowBytes, pitched.data() + row * layout.rowPitch,
                    layout.tightRowBytes);
}

}  // namespace caustics::rhi::d3d12
