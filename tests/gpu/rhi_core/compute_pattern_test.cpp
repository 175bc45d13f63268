// A compute shader writes a closed-form pattern into a storage buffer and a storage image; the
// readback must equal the CPU formula bit for bit (integer arithmetic: no tolerance).
#include <cstring>

#include "gpu_test.h"

namespace caustics::test {
namespace {
using namespace rhi;

constexpr uint32_t kWidth = 37, kHeight = 21, kSeed = 0x5eedu;   // odd sizes exercise the bounds check

TEST_F(GpuTest, ComputePatternMatchesCpuFormulaInBufferAndImage) {
    auto layout = device->createBindingLayout(BindingLayoutDesc()
                                                  .setVisibility(ShaderStage::Compute)
                                                  .add(0, BindingType::StorageBufferRW)
                                                  .add(1, BindingType::StorageTexture));
    ASSERT_TRUE(layout.ok()) << layout.message();
    ComputePipelineDesc pd;
    pd.shader.code = testShader("rhi_core/pattern.comp");
    pd.bindings.layouts = {layout.value()};
    pd.bindings.pushConstantBytes = 12;
    pd.debugName = "pattern";
    auto pipeline = device->createComputePipeline(pd);
    ASSERT_TRUE(pipeline.ok()) << pipeline.message();

    const uint64_t bufferBytes = uint64_t(kWidth) * kHeight * 4;
    auto buffer = device->createBuffer(BufferDesc().setByteSize(bufferBytes).setDebugName("pattern buffer"));
    auto image = device->createTexture(TextureDesc()
                                           .setSize(kWidth, kHeight)
                                           .setFormat(Format::R32_UINT)
                                           .setUsage(TextureUsage::Storage | TextureUsage::CopySource)
                                           .setDebugName("pattern image"));
    ASSERT_TRUE(buffer.ok() && image.ok());
    auto set = device->createBindingSet(BindingSetDesc()
                                            .add(BindingSetItem::storageBuffer(0, buffer.value()))
                                            .add(BindingSetItem::storageTexture(1, image.value())),
                                        layout.value());
    ASSERT_TRUE(set.ok()) << set.message();
    BufferHandle readback = createReadback(bufferBytes);

    runCommands([&](ICommandList& cmd) {
        cmd.barrier(TextureBarrier{image.value(), ResourceState::Undefined, ResourceState::UnorderedAccess});
        cmd.barrier(BufferBarrier{buffer.value(), ResourceState::Undefined, ResourceState::UnorderedAccess});
        cmd.setComputePipeline(pipeline.value());
        cmd.setBindingSet(0, set.value());
        const uint32_t push[3] = {kWidth, kHeight, kSeed};
        cmd.setPushConstants(push, sizeof(push));
        cmd.dispatch((kWidth + 7) / 8, (kHeight + 7) / 8);
        cmd.barrier(BufferBarrier{buffer.value(), ResourceState::UnorderedAccess, ResourceState::CopySource});
        cmd.barrier(TextureBarrier{image.value(), ResourceState::UnorderedAccess, ResourceState::CopySource});
        cmd.copyBuffer(readback, 0, buffer.value(), 0, bufferBytes);
    });

    std::vector<uint8_t> bufferBytesRead = readBuffer(readback, bufferBytes);
    std::vector<uint8_t> imageBytes = readTexture(image.value());
    ASSERT_EQ(imageBytes.size(), bufferBytes);
    uint32_t mismatches = 0;
    for (uint32_t y = 0; y < kHeight; ++y)
        for (uint32_t x = 0; x < kWidth; ++x) {
            const uint32_t i = y * kWidth + x;
            uint32_t fromBuffer, fromImage;
            std::memcpy(&fromBuffer, &bufferBytesRead[i * 4], 4);
            std::memcpy(&fromImage, &imageBytes[i * 4], 4);
            if (fromBuffer != ((i * 2654435761u) ^ kSeed)) ++mismatches;
            if (fromImage != x * 1000u + y + kSeed) ++mismatches;
        }
    EXPECT_EQ(mismatches, 0u);
}

}  // namespace
}  // namespace caustics::test
