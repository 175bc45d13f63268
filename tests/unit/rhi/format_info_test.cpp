#include "caustics/rhi/format.h"

#include <gtest/gtest.h>

#include <cstring>

namespace caustics::rhi {
namespace {

TEST(FormatInfo, BytesPerPixelMatchChannelLayout) {
    EXPECT_EQ(formatInfo(Format::R8_UNORM).bytesPerPixel, 1u);
    EXPECT_EQ(formatInfo(Format::RGBA8_UNORM).bytesPerPixel, 4u);
    EXPECT_EQ(formatInfo(Format::RGBA16_FLOAT).bytesPerPixel, 8u);
    EXPECT_EQ(formatInfo(Format::RGB32_FLOAT).bytesPerPixel, 12u);
    EXPECT_EQ(formatInfo(Format::RGBA32_FLOAT).bytesPerPixel, 16u);
    EXPECT_EQ(formatInfo(Format::R32_UINT).bytesPerPixel, 4u);
}

TEST(FormatInfo, DepthAndIntegerFlags) {
    EXPECT_TRUE(formatInfo(Format::D32_FLOAT).isDepth);
    EXPECT_FALSE(formatInfo(Format::D32_FLOAT).hasStencil);
    EXPECT_TRUE(formatInfo(Format::D24_UNORM_S8_UINT).hasStencil);
    EXPECT_TRUE(formatInfo(Format::R32_UINT).isInteger);
    EXPECT_FALSE(formatInfo(Format::R32_FLOAT).isInteger);
    EXPECT_FALSE(formatInfo(Format::RGBA8_UNORM).isDepth);
}

TEST(FormatInfo, NamesFollowTheEnum) {
    EXPECT_STREQ(formatInfo(Format::RGBA16_FLOAT).name, "RGBA16_FLOAT");
    EXPECT_STREQ(formatInfo(Format::D24_UNORM_S8_UINT).name, "D24_UNORM_S8_UINT");
}

TEST(FormatInfo, OutOfRangeFallsBackToUnknown) {
    EXPECT_STREQ(formatInfo(Format(999)).name, "Unknown");
}

}  // namespace
}  // namespace caustics::rhi
