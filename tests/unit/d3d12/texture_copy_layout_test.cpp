#include <gtest/gtest.h>

#include <numeric>
#include <vector>

#include "texture_copy_layout.h"

namespace caustics::rhi::d3d12 {
namespace {

TextureDesc texture(uint32_t w, uint32_t h, Format f, uint32_t layers = 1, uint32_t mips = 1) {
    TextureDesc d;
    d.setSize(w, h).setFormat(f).setArrayLayers(layers).setMipLevels(mips);
    return d;
}

TEST(D3D12TextureCopyLayout, RowPitchIsTightRowAlignedUpTo256Bytes) {
    auto l = textureCopyLayout(texture(33, 5, Format::RGBA8_UNORM), 0, 0);
    ASSERT_TRUE(l.ok());
    EXPECT_EQ(l->tightRowBytes, 132u);
    EXPECT_EQ(l->rowPitch, 256u);
    EXPECT_EQ(l->tightBytes, 132u * 5);
    EXPECT_EQ(l->stagingBytes, 256u * 5);
}

TEST(D3D12TextureCopyLayout, AlignedRowsKeepTheirPitch) {
    auto l = textureCopyLayout(texture(64, 2, Format::RGBA32_FLOAT), 0, 0);   // 64 x 16 = 1024 bytes
    ASSERT_TRUE(l.ok());
    EXPECT_EQ(l->rowPitch, 1024u);
}

TEST(D3D12TextureCopyLayout, MipLevelHalvesTheSizeAndNeverReachesZero) {
    auto l = textureCopyLayout(texture(16, 4, Format::R32_FLOAT, 1, 5), 0, 4);
    ASSERT_TRUE(l.ok());
    EXPECT_EQ(l->width, 1u);
    EXPECT_EQ(l->height, 1u);
    EXPECT_EQ(l->tightRowBytes, 4u);
}

TEST(D3D12TextureCopyLayout, SubresourceIndexIsMipPlusLayerTimesMipCount) {
    auto l = textureCopyLayout(texture(8, 8, Format::R8_UNORM, 6, 3), 4, 2);   // D3D12CalcSubresource
    ASSERT_TRUE(l.ok());
    EXPECT_EQ(l->subresource, 2u + 4u * 3u);
}

TEST(D3D12TextureCopyLayout, OutOfRangeLayerOrMipIsRefused) {
    EXPECT_FALSE(textureCopyLayout(texture(8, 8, Format::R8_UNORM, 2, 1), 2, 0).ok());
    EXPECT_FALSE(textureCopyLayout(texture(8, 8, Format::R8_UNORM, 2, 1), 0, 1).ok());
}

TEST(D3D12TextureCopyLayout, DirectCopyNeedsAlignedRowsAndA512ByteOffset) {
    auto aligned = textureCopyLayout(texture(64, 2, Format::RGBA8_UNORM), 0, 0);   // 256-byte rows
    auto unaligned = textureCopyLayout(texture(3, 2, Format::RGBA8_UNORM), 0, 0);
    ASSERT_TRUE(aligned.ok() && unaligned.ok());
    EXPECT_TRUE(copyNeedsNoRepack(*aligned, 1024));
    EXPECT_FALSE(copyNeedsNoRepack(*aligned, 256));   // D3D12_TEXTURE_DATA_PLACEMENT_ALIGNMENT = 512
    EXPECT_FALSE(copyNeedsNoRepack(*unaligned, 0));
}

TEST(D3D12TextureCopyLayout, PackThenUnpackRestoresTightRows) {
    auto l = textureCopyLayout(texture(3, 4, Format::RG16_FLOAT), 0, 0);   // 12-byte rows, pitch 256
    ASSERT_TRUE(l.ok());
    std::vector<uint8_t> tight(l->tightBytes), pitched(l->stagingBytes, 0xEE), back(l->tightBytes);
    std::iota(tight.begin(), tight.end(), uint8_t(1));
    packRowsToPitch(*l, tight, pitched);
    EXPECT_EQ(pitched[256], tight[12]);       // row 1 starts at the pitch
    EXPECT_EQ(pitched[12], 0xEE);             // padding untouched
    unpackRowsFromPitch(*l, pitched, back);
    EXPECT_EQ(back, tight);
}

}  // namespace
}  // namespace caustics::rhi::d3d12
