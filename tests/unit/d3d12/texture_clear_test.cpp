#include <gtest/gtest.h>

#include <bit>
#include <cstring>

#include "debug_marker.h"
#include "texture_clear.h"

namespace caustics::rhi::d3d12 {
namespace {

TextureDesc withUsage(Format f, TextureUsage u) {
    TextureDesc d;
    d.setFormat(f).setUsage(u | TextureUsage::CopyDest);
    return d;
}

TEST(D3D12TextureClear, StorageTexturesClearThroughAUavOfTheMatchingKind) {
    EXPECT_EQ(chooseClearMethod(withUsage(Format::RGBA32_FLOAT, TextureUsage::Storage), false), ClearMethod::UavFloat);
    EXPECT_EQ(chooseClearMethod(withUsage(Format::R32_UINT, TextureUsage::Storage), true), ClearMethod::UavUint);
}

TEST(D3D12TextureClear, MismatchedValueKindFallsBackToACopy) {
    // Bit patterns of a float UAV cannot be written by ClearUnorderedAccessViewUint's conversion.
    EXPECT_EQ(chooseClearMethod(withUsage(Format::R32_FLOAT, TextureUsage::Storage), true), ClearMethod::Copy);
    EXPECT_EQ(chooseClearMethod(withUsage(Format::R32_UINT, TextureUsage::RenderTarget), true), ClearMethod::Copy);
}

TEST(D3D12TextureClear, RenderTargetsAndDepthUseTheirViews) {
    EXPECT_EQ(chooseClearMethod(withUsage(Format::RGBA16_FLOAT, TextureUsage::RenderTarget), false),
              ClearMethod::RenderTarget);
    EXPECT_EQ(chooseClearMethod(withUsage(Format::D32_FLOAT, TextureUsage::DepthStencil), false),
              ClearMethod::DepthStencil);
    EXPECT_EQ(chooseClearMethod(withUsage(Format::RGBA8_UNORM, TextureUsage::Sampled), false), ClearMethod::Copy);
}

TEST(D3D12TextureClear, Unorm8RoundsAndSaturates) {
    const float v[4] = {0.5f, 2.0f, -1.0f, 1.0f};
    EXPECT_EQ(encodeClearPixel(Format::RGBA8_UNORM, v), (std::vector<uint8_t>{128, 255, 0, 255}));
}

TEST(D3D12TextureClear, BgraSwapsRedAndBlue) {
    const float v[4] = {1.0f, 0.0f, 0.0f, 1.0f};
    EXPECT_EQ(encodeClearPixel(Format::BGRA8_UNORM, v), (std::vector<uint8_t>{0, 0, 255, 255}));
}

TEST(D3D12TextureClear, SrgbEncodesColourButNotAlpha) {
    const float v[4] = {0.5f, 0.0f, 1.0f, 0.5f};
    // IEC 61966-2-1: 1.055 x 0.5^(1/2.4) - 0.055 = 0.7354 -> 188 of 255.
    EXPECT_EQ(encodeClearPixel(Format::RGBA8_SRGB, v), (std::vector<uint8_t>{188, 0, 255, 128}));
}

TEST(D3D12TextureClear, HalfFloatsAreIeeeBinary16) {
    EXPECT_EQ(floatToHalf(1.0f), 0x3C00);
    EXPECT_EQ(floatToHalf(-2.0f), 0xC000);
    EXPECT_EQ(floatToHalf(65504.0f), 0x7BFF);
    EXPECT_EQ(floatToHalf(1.0e6f), 0x7C00);          // overflow -> infinity
    EXPECT_EQ(floatToHalf(5.9604645e-8f), 0x0001);   // smallest subnormal 2^-24
    EXPECT_EQ(floatToHalf(1.0f + 1.0f / 2048.0f), 0x3C00);   // tie rounds to even
    EXPECT_EQ(floatToHalf(1.0f + 3.0f / 2048.0f), 0x3C02);   // tie rounds to even (up)
}

TEST(D3D12TextureClear, UintValuesOnFloatFormatsAreBitPatterns) {
    const uint32_t v[4] = {std::bit_cast<uint32_t>(2.5f), 0, 0, 0};
    std::vector<uint8_t> px = encodeClearPixel(Format::R32_FLOAT, v);
    ASSERT_EQ(px.size(), 4u);
    float f;
    std::memcpy(&f, px.data(), 4);
    EXPECT_EQ(f, 2.5f);
}

// The packed HDR formats: R11G11B10_FLOAT keeps the half's exponent and its top 6 (red, green) or 5
// (blue) mantissa bits; RGB10A2_UNORM rounds to 1023 and 3 steps, red in the low bits.
TEST(D3D12TextureClear, PackedFormatsPutEachChannelInItsBits) {
    const float hdr[4] = {1.0f, 0.5f, 2.0f, 0.0f};
    std::vector<uint8_t> px = encodeClearPixel(Format::R11G11B10_FLOAT, hdr);
    ASSERT_EQ(px.size(), 4u);
    uint32_t bits;
    std::memcpy(&bits, px.data(), 4);
    EXPECT_EQ(bits, 0x3C0u | 0x380u << 11 | 0x200u << 22);
    const float ldr[4] = {1.0f, 0.0f, 0.5f, 1.0f};
    px = encodeClearPixel(Format::RGB10A2_UNORM, ldr);
    ASSERT_EQ(px.size(), 4u);
    std::memcpy(&bits, px.data(), 4);
    EXPECT_EQ(bits, 1023u | 512u << 20 | 3u << 30);
}

TEST(D3D12TextureClear, PixelSizeMatchesTheFormat) {
    const float v[4] = {1, 1, 1, 1};
    for (uint32_t f = 1; f <= uint32_t(kLastFormat); ++f)
        EXPECT_EQ(encodeClearPixel(Format(f), v).size(), formatInfo(Format(f)).bytesPerPixel) << formatInfo(Format(f)).name;
}

TEST(D3D12DebugMarker, PayloadIsNullTerminatedUtf16) {
    EXPECT_EQ(markerPayload("gbuffer"), std::u16string(u"gbuffer") + u'\0');
}

TEST(D3D12DebugMarker, MultiByteUtf8BecomesUtf16WithSurrogates) {
    // "é" (C3 A9) -> U+00E9; U+1F600 (F0 9F 98 80) -> D83D DE00.
    EXPECT_EQ(markerPayload("\xC3\xA9\xF0\x9F\x98\x80"), (std::u16string{0x00E9, 0xD83D, 0xDE00, 0}));
}

TEST(D3D12DebugMarker, InvalidBytesBecomeReplacementCharacters) {
    EXPECT_EQ(markerPayload("a\xFF"), (std::u16string{u'a', 0xFFFD, 0}));
    EXPECT_EQ(markerPayload("\xC3"), (std::u16string{0xFFFD, 0}));   // truncated sequence
}

}  // namespace
}  // namespace caustics::rhi::d3d12
