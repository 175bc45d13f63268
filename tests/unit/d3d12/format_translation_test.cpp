#include <gtest/gtest.h>

#include "format_translation.h"

namespace caustics::rhi::d3d12 {
namespace {

TEST(D3D12Formats, EveryRhiFormatButUnknownHasADxgiFormat) {
    for (uint32_t f = 1; f <= uint32_t(kLastFormat); ++f)
        EXPECT_NE(toDxgiFormat(Format(f)), DXGI_FORMAT_UNKNOWN) << formatInfo(Format(f)).name;
    EXPECT_EQ(toDxgiFormat(Format::Unknown), DXGI_FORMAT_UNKNOWN);
}

TEST(D3D12Formats, ColourFormatsMapToTheirDxgiTwins) {
    EXPECT_EQ(toDxgiFormat(Format::RGBA16_FLOAT), DXGI_FORMAT_R16G16B16A16_FLOAT);
    EXPECT_EQ(toDxgiFormat(Format::RGBA8_SRGB), DXGI_FORMAT_R8G8B8A8_UNORM_SRGB);
    EXPECT_EQ(toDxgiFormat(Format::BGRA8_UNORM), DXGI_FORMAT_B8G8R8A8_UNORM);
    EXPECT_EQ(toDxgiFormat(Format::R32_UINT), DXGI_FORMAT_R32_UINT);   // caustic buffer atomics
    EXPECT_EQ(toDxgiFormat(Format::RGB32_FLOAT), DXGI_FORMAT_R32G32B32_FLOAT);
}

TEST(D3D12Formats, DepthIsTypelessAsAResourceAndTypedPerView) {
    EXPECT_EQ(toDxgiResourceFormat(Format::D32_FLOAT), DXGI_FORMAT_R32_TYPELESS);
    EXPECT_EQ(toDxgiDsvFormat(Format::D32_FLOAT), DXGI_FORMAT_D32_FLOAT);
    EXPECT_EQ(toDxgiSrvFormat(Format::D32_FLOAT), DXGI_FORMAT_R32_FLOAT);
    EXPECT_EQ(toDxgiResourceFormat(Format::D24_UNORM_S8_UINT), DXGI_FORMAT_R24G8_TYPELESS);
    EXPECT_EQ(toDxgiSrvFormat(Format::D24_UNORM_S8_UINT), DXGI_FORMAT_R24_UNORM_X8_TYPELESS);
}

TEST(D3D12Formats, ColourFormatsHaveNoDsvFormat) {
    EXPECT_EQ(toDxgiDsvFormat(Format::RGBA8_UNORM), DXGI_FORMAT_UNKNOWN);
    EXPECT_EQ(toDxgiResourceFormat(Format::RGBA8_UNORM), DXGI_FORMAT_R8G8B8A8_UNORM);
}

}  // namespace
}  // namespace caustics::rhi::d3d12
