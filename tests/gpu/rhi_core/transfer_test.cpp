// Round trips through fillBuffer, writeBuffer (inline and staged), copyBuffer and writeTexture.
#include <cstring>
#include <numeric>

#include "gpu_test.h"

namespace caustics::test {
namespace {
using namespace rhi;

BufferHandle deviceBuffer(IDevice& device, uint64_t bytes, const char* name) {
    auto b = device.createBuffer(BufferDesc().setByteSize(bytes).setDebugName(name));
    EXPECT_TRUE(b.ok()) << (b.ok() ? "" : b.message());
    return b.ok() ? b.value() : nullptr;
}

TEST_F(GpuTest, FillBufferThenCopyBufferReadsBackTheFilledRangeOnly) {
    constexpr uint64_t kBytes = 1024;
    BufferHandle buffer = deviceBuffer(*device, kBytes, "filled");
    BufferHandle readback = createReadback(kBytes);
    runCommands([&](ICommandList& cmd) {
        cmd.barrier(BufferBarrier{buffer, ResourceState::Undefined, ResourceState::CopyDest});
        cmd.fillBuffer(buffer, 0u);
        cmd.barrier(BufferBarrier{buffer, ResourceState::CopyDest, ResourceState::CopyDest});
        cmd.fillBuffer(buffer, 0xABCD1234u, 256, 512);
        cmd.barrier(BufferBarrier{buffer, ResourceState::CopyDest, ResourceState::CopySource});
        cmd.copyBuffer(readback, 0, buffer, 0, kBytes);
    });
    std::vector<uint8_t> bytes = readBuffer(readback, kBytes);
    for (uint64_t i = 0; i < kBytes; i += 4) {
        uint32_t v;
        std::memcpy(&v, &bytes[i], 4);
        EXPECT_EQ(v, (i >= 256 && i < 768) ? 0xABCD1234u : 0u) << "at byte " << i;
    }
}

// 64 KiB is vkCmdUpdateBuffer's limit: the small write goes inline, the large one through staging.
TEST_F(GpuTest, WriteBufferRoundTripsSmallAndLargeData) {
    for (uint64_t bytes : {uint64_t(256), uint64_t(200000)}) {
        std::vector<uint8_t> data(bytes);
        for (uint64_t i = 0; i < bytes; ++i) data[i] = uint8_t(i * 31 + 7);
        BufferHandle buffer = deviceBuffer(*device, bytes, "written");
        BufferHandle readback = createReadback(bytes);
        runCommands([&](ICommandList& cmd) {
            cmd.barrier(BufferBarrier{buffer, ResourceState::Undefined, ResourceState::CopyDest});
            cmd.writeBuffer(buffer, data.data(), bytes);
            cmd.barrier(BufferBarrier{buffer, ResourceState::CopyDest, ResourceState::CopySource});
            cmd.copyBuffer(readback, 0, buffer, 0, bytes);
        });
        EXPECT_EQ(readBuffer(readback, bytes), data) << bytes << " bytes";
    }
}

TEST_F(GpuTest, WriteTextureRoundTripsIntoAnArrayLayer) {
    constexpr uint32_t kW = 16, kH = 8;
    auto texture = device->createTexture(TextureDesc()
                                             .setDimension(TextureDimension::Texture2DArray)
                                             .setSize(kW, kH)
                                             .setArrayLayers(2)
                                             .setFormat(Format::RGBA16_FLOAT)
                                             .setDebugName("array"));
    ASSERT_TRUE(texture.ok()) << texture.message();
    std::vector<uint8_t> data(kW * kH * 8);
    for (size_t i = 0; i < data.size(); ++i) data[i] = uint8_t(i * 13 + 1);
    runCommands([&](ICommandList& cmd) {
        cmd.barrier(TextureBarrier{texture.value(), ResourceState::Undefined, ResourceState::CopyDest});
        cmd.writeTexture(texture.value(), 1, 0, data.data(), data.size());
        cmd.barrier(TextureBarrier{texture.value(), ResourceState::CopyDest, ResourceState::CopySource});
    });
    EXPECT_EQ(readTexture(texture.value(), ResourceState::CopySource, 1), data);
}

TEST_F(GpuTest, ClearTextureUintFillsEveryTexel) {
    auto texture = device->createTexture(
        TextureDesc().setSize(8, 8).setFormat(Format::R32_UINT).setUsage(TextureUsage::Storage).setDebugName("cleared"));
    ASSERT_TRUE(texture.ok()) << texture.message();
    const uint32_t value[4] = {0xC0FFEEu, 0, 0, 0};
    runCommands([&](ICommandList& cmd) {
        cmd.barrier(TextureBarrier{texture.value(), ResourceState::Undefined, ResourceState::CopyDest});
        cmd.clearTextureUint(texture.value(), value);
        cmd.barrier(TextureBarrier{texture.value(), ResourceState::CopyDest, ResourceState::CopySource});
    });
    std::vector<uint8_t> bytes = readTexture(texture.value());
    ASSERT_EQ(bytes.size(), 8u * 8u * 4u);
    for (size_t i = 0; i < bytes.size(); i += 4) {
        uint32_t v;
        std::memcpy(&v, &bytes[i], 4);
        EXPECT_EQ(v, 0xC0FFEEu);
    }
}

}  // namespace
}  // namespace caustics::test
