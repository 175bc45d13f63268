// ICommandList::copyTexture: a rectangle of one texture lands at an offset of another, byte for byte,
// and regions outside a texture are refused naming it.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "gpu_test.h"

namespace caustics::test {
namespace {
using namespace rhi;

class TextureCopy : public GpuTest {
protected:
    TextureHandle makeTexture(uint32_t w, uint32_t h, Format format, uint32_t layers, const std::string& name) {
        auto t = device->createTexture(TextureDesc()
                                           .setSize(w, h)
                                           .setFormat(format)
                                           .setArrayLayers(layers)
                                           .setDimension(layers > 1 ? TextureDimension::Texture2DArray
                                                                    : TextureDimension::Texture2D)
                                           .setUsage(TextureUsage::CopySource | TextureUsage::CopyDest)
                                           .setDebugName(name));
        EXPECT_TRUE(t.ok()) << (t.ok() ? "" : t.message());
        return t.ok() ? t.value() : nullptr;
    }
    // Records a whole-texture copy and returns submit's error ("" if it was accepted).
    std::string refusal(const TextureHandle& dst, const TextureHandle& src) {
        auto cmd = device->createCommandList();
        EXPECT_TRUE(cmd.ok());
        if (!cmd) return "";
        cmd.value()->begin();
        cmd.value()->copyTexture(dst, TextureRegion(), src, TextureRegion());
        cmd.value()->end();
        auto fence = device->submit(cmd.value());
        return fence.ok() ? std::string() : fence.message();
    }
};

// Texel (x, y) of the source holds 4 distinct bytes so any misplaced texel shows.
uint32_t sourceTexel(uint32_t x, uint32_t y) { return 0x01000000u | (y << 8) | x; }

TEST_F(TextureCopy, RectangleLandsAtDestinationOffsetAndLayerExactly) {
    constexpr uint32_t kSrcW = 16, kSrcH = 8, kDstW = 32, kDstH = 16;
    TextureHandle src = makeTexture(kSrcW, kSrcH, Format::RGBA8_UNORM, 1, "copy source");
    TextureHandle dst = makeTexture(kDstW, kDstH, Format::R32_UINT, 2, "copy destination");
    ASSERT_TRUE(src && dst);
    std::vector<uint32_t> pixels(kSrcW * kSrcH);
    for (uint32_t y = 0; y < kSrcH; ++y)
        for (uint32_t x = 0; x < kSrcW; ++x) pixels[y * kSrcW + x] = sourceTexel(x, y);
    const uint32_t zero[4] = {0, 0, 0, 0};
    // RGBA8 and R32_UINT are both 4 bytes per texel: a copy moves the bits unchanged.
    const TextureRegion from = TextureRegion().setOffset(3, 2).setSize(6, 4);
    const TextureRegion to = TextureRegion().setLayer(1).setOffset(10, 5);
    runCommands([&](ICommandList& cmd) {
        cmd.barrier(TextureBarrier{src, ResourceState::Undefined, ResourceState::CopyDest});
        cmd.barrier(TextureBarrier{dst, ResourceState::Undefined, ResourceState::CopyDest});
        cmd.writeTexture(src, 0, 0, pixels.data(), pixels.size() * 4);
        cmd.clearTextureUint(dst, zero);
        cmd.barrier(TextureBarrier{src, ResourceState::CopyDest, ResourceState::CopySource});
        cmd.barrier(TextureBarrier{dst, ResourceState::CopyDest, ResourceState::CopyDest});   // clear, then copy
        cmd.copyTexture(dst, to, src, from);
        cmd.barrier(TextureBarrier{dst, ResourceState::CopyDest, ResourceState::CopySource});
    });
    for (uint32_t layer = 0; layer < 2; ++layer) {
        std::vector<uint8_t> bytes = readTexture(dst, ResourceState::CopySource, layer);
        ASSERT_EQ(bytes.size(), kDstW * kDstH * 4u);
        uint32_t mismatches = 0;
        for (uint32_t y = 0; y < kDstH; ++y)
            for (uint32_t x = 0; x < kDstW; ++x) {
                uint32_t got;
                std::memcpy(&got, bytes.data() + (y * kDstW + x) * 4, 4);
                const bool inside = layer == 1 && x >= 10 && x < 16 && y >= 5 && y < 9;
                const uint32_t expected = inside ? sourceTexel(x - 10 + 3, y - 5 + 2) : 0u;
                if (got != expected && ++mismatches <= 5)
                    ADD_FAILURE() << "layer " << layer << " texel (" << x << "," << y << "): got 0x" << std::hex << got
                                  << ", expected 0x" << expected;
            }
        EXPECT_EQ(mismatches, 0u) << "layer " << layer;
    }
}

TEST_F(TextureCopy, RegionOutsideTheDestinationIsRefusedNamingIt) {
    TextureHandle src = makeTexture(8, 8, Format::RGBA8_UNORM, 1, "small source");
    TextureHandle dst = makeTexture(4, 4, Format::RGBA8_UNORM, 1, "tiny destination");
    ASSERT_TRUE(src && dst);
    const std::string message = refusal(dst, src);   // 8x8 into 4x4
    EXPECT_NE(message.find("'tiny destination'"), std::string::npos) << message;
    EXPECT_NE(message.find("outside"), std::string::npos) << message;
}

TEST_F(TextureCopy, FormatsOfDifferentTexelSizeAreRefused) {
    TextureHandle src = makeTexture(4, 4, Format::RGBA16_FLOAT, 1, "wide source");
    TextureHandle dst = makeTexture(4, 4, Format::RGBA8_UNORM, 1, "narrow destination");
    ASSERT_TRUE(src && dst);
    const std::string message = refusal(dst, src);
    EXPECT_NE(message.find("not copy-compatible"), std::string::npos) << message;
}

}  // namespace
}  // namespace caustics::test
