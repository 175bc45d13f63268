// checkTextureCopy (core/texture_copy_check.h), shared by both backends' copyTexture.
#include <gtest/gtest.h>

#include "core/texture_copy_check.h"

namespace caustics::rhi {
namespace {

TextureDesc texture(uint32_t w, uint32_t h, Format format, const char* name, uint32_t mips = 1, uint32_t layers = 1) {
    return TextureDesc().setSize(w, h).setFormat(format).setMipLevels(mips).setArrayLayers(layers).setDebugName(name);
}

TEST(TextureCopyCheck, ZeroSizeMeansToTheEdgeOfTheSourceMip) {
    auto extent = checkTextureCopy(texture(64, 64, Format::RGBA8_UNORM, "dst"), TextureRegion(),
                                   texture(40, 30, Format::RGBA8_UNORM, "src", 2), TextureRegion().setMip(1).setOffset(4, 5));
    ASSERT_TRUE(extent.ok()) << extent.message();
    EXPECT_EQ(extent->width, 20u - 4u);
    EXPECT_EQ(extent->height, 15u - 5u);
}

TEST(TextureCopyCheck, SameTexelSizeIsCompatibleAcrossFormats) {
    EXPECT_TRUE(checkTextureCopy(texture(4, 4, Format::R32_UINT, "dst"), TextureRegion(),
                                 texture(4, 4, Format::R32_FLOAT, "src"), TextureRegion()).ok());
    auto depth = checkTextureCopy(texture(4, 4, Format::R32_FLOAT, "colour"), TextureRegion(),
                                  texture(4, 4, Format::D32_FLOAT, "depth"), TextureRegion());
    EXPECT_FALSE(depth.ok());
}

TEST(TextureCopyCheck, OutOfRangeLayerMipAndRectangleNameTheTexture) {
    const TextureDesc src = texture(8, 8, Format::RGBA8_UNORM, "src", 1, 2);
    const TextureDesc dst = texture(8, 8, Format::RGBA8_UNORM, "dst");
    auto layer = checkTextureCopy(dst, TextureRegion().setLayer(1), src, TextureRegion());
    ASSERT_FALSE(layer.ok());
    EXPECT_NE(layer.message().find("layer 1 of 'dst'"), std::string::npos) << layer.message();
    auto mip = checkTextureCopy(dst, TextureRegion(), src, TextureRegion().setMip(3));
    ASSERT_FALSE(mip.ok());
    EXPECT_NE(mip.message().find("mip 3 of 'src'"), std::string::npos) << mip.message();
    auto rect = checkTextureCopy(dst, TextureRegion().setOffset(6, 0), src, TextureRegion().setSize(4, 4));
    ASSERT_FALSE(rect.ok());
    EXPECT_NE(rect.message().find("outside 'dst'"), std::string::npos) << rect.message();
}

}  // namespace
}  // namespace caustics::rhi
