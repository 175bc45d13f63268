// ICommandList::copyTexture on D3D12: one CopyTextureRegion between two subresources, the source box
// being the checked region (../core/texture_copy_check.h). Texture states are the caller's (CopySource /
// CopyDest through barriers), as for the other copies.
#include "../core/texture_copy_check.h"
#include "d3d12_command_list.h"

namespace caustics::rhi::d3d12 {

void CommandList::copyTexture(const TextureHandle& dstHandle, const TextureRegion& dstRegion,
                              const TextureHandle& srcHandle, const TextureRegion& srcRegion) {
    auto* dst = static_cast<Texture*>(dstHandle.get());
    auto* src = static_cast<Texture*>(srcHandle.get());
    auto extent = checkTextureCopy(dst->desc_, dstRegion, src->desc_, srcRegion);
    if (!extent) return fail(makeError("d3d12: " + extent.message()));
    auto subresource = [](const TextureDesc& d, const TextureRegion& r) {
        return r.mip + r.layer * d.mipLevels;   // D3D12CalcSubresource without planes
    };
    D3D12_TEXTURE_COPY_LOCATION to{};
    to.pResource = dst->resource.get();
    to.Type = D3D12_TEXTURE_COPY_TYPE_SUBRESOURCE_INDEX;
    to.SubresourceIndex = subresource(dst->desc_, dstRegion);
    D3D12_TEXTURE_COPY_LOCATION from{};
    from.pResource = src->resource.get();
    from.Type = D3D12_TEXTURE_COPY_TYPE_SUBRESOURCE_INDEX;
    from.SubresourceIndex = subresource(src->desc_, srcRegion);
    const D3D12_BOX box{srcRegion.x, srcRegion.y, 0, srcRegion.x + extent->width, srcRegion.y + extent->height, 1};
    list->CopyTextureRegion(&to, dstRegion.x, dstRegion.y, 0, &from, &box);
}

}  // namespace caustics::rhi::d3d12
