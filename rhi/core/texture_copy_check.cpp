#include "texture_copy_check.h"

#include <algorithm>
#include <string>

namespace caustics::rhi {
namespace {

std::string describe(const TextureDesc& d) { return "'" + d.debugName + "'"; }

// Empty when `region` (with the given extent) lies in a mip/layer of `d`, otherwise why not.
std::string outside(const TextureDesc& d, const TextureRegion& region, uint32_t width, uint32_t height) {
    if (region.mip >= d.mipLevels)
        return "mip " + std::to_string(region.mip) + " of " + describe(d) + " (it has " + std::to_string(d.mipLevels) + ")";
    if (region.layer >= d.arrayLayers)
        return "layer " + std::to_string(region.layer) + " of " + describe(d) + " (it has " +
               std::to_string(d.arrayLayers) + ")";
    const uint32_t mipWidth = std::max(1u, d.width >> region.mip), mipHeight = std::max(1u, d.height >> region.mip);
    if (uint64_t(region.x) + width > mipWidth || uint64_t(region.y) + height > mipHeight)
        return "rectangle " + std::to_string(width) + "x" + std::to_string(height) + " at (" +
               std::to_string(region.x) + "," + std::to_string(region.y) + ") outside " + describe(d) + " mip " +
               std::to_string(region.mip) + " (" + std::to_string(mipWidth) + "x" + std::to_string(mipHeight) + ")";
    return {};
}

}  // namespace

Result<TextureCopyExtent> checkTextureCopy(const TextureDesc& dst, const TextureRegion& dstRegion,
                                           const TextureDesc& src, const TextureRegion& srcRegion) {
    const std::string what = "copyTexture " + describe(src) + " -> " + describe(dst) + ": ";
    const FormatInfo& sf = formatInfo(src.format);
    const FormatInfo& df = formatInfo(dst.format);
    if (sf.bytesPerPixel != df.bytesPerPixel || sf.isDepth != df.isDepth)
        return makeError(what + "formats " + sf.name + " and " + df.name + " are not copy-compatible");
    if (srcRegion.mip < src.mipLevels && srcRegion.x > std::max(1u, src.width >> srcRegion.mip))
        return makeError(what + "source x " + std::to_string(srcRegion.x) + " outside " + describe(src));
    if (srcRegion.mip < src.mipLevels && srcRegion.y > std::max(1u, src.height >> srcRegion.mip))
        return makeError(what + "source y " + std::to_string(srcRegion.y) + " outside " + describe(src));
    TextureCopyExtent extent;
    if (srcRegion.mip < src.mipLevels) {
        extent.width = srcRegion.width ? srcRegion.width : std::max(1u, src.width >> srcRegion.mip) - srcRegion.x;
        extent.height = srcRegion.height ? srcRegion.height : std::max(1u, src.height >> srcRegion.mip) - srcRegion.y;
    }
    if (std::string why = outside(src, srcRegion, extent.width, extent.height); !why.empty())
        return makeError(what + "source " + why);
    if (std::string why = outside(dst, dstRegion, extent.width, extent.height); !why.empty())
        return makeError(what + "destination " + why);
    if (extent.width == 0 || extent.height == 0) return makeError(what + "empty rectangle");
    return extent;
}

}  // namespace caustics::rhi
