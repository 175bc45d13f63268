// The output target outside caustics-only mode (the display image) and the targets the module refuses
// (docs/embedding.md "Output target"): each refusal names the field, the texture, its format and what is
// needed.
#include "output_target_host.h"

namespace caustics::test {
namespace {

// Outside caustics-only mode the target takes the display image (RGBA8_UNORM, Storage). The host need
// not mark it as an output: the module keeps the passes that write it (they used to be culled without
// a word, the target left as it was). Same frame, same seed: the bytes equal the display transient's.
TEST_F(OutputTarget, DisplayIntoHostTargetEqualsTheDisplayImageWithoutMarkingIt) {
    CausticsSettings s;
    s.causticsEnabled = false;   // direct light alone: the display path is what is tested
    auto standalone = CausticsModule::create(device, scene_, *gpuScene_, s);
    ASSERT_TRUE(standalone) << standalone.message();
    auto run = [&](const rhi::TextureHandle& target, const rhi::TextureHandle& copy) -> Status {
        rg::RenderGraph graph;
        FrameInputs in = viewOf(spotSphereCamera(), kTargetSize).inputs;
        in.outputTarget = target;
        in.outputState = rhi::ResourceState::CopySource;
        CAUSTICS_TRY(FrameOutputs out, standalone.value()->addPasses(graph, in));
        if (copy) copyInto(graph, out.display, copy, rhi::ResourceState::Undefined, rhi::ResourceState::CopySource);
        CAUSTICS_TRY(rhi::CommandListHandle cmd, device->createCommandList());
        cmd->begin();
        if (target) {
            const rhi::TextureBarrier toClear{.texture = target, .before = rhi::ResourceState::Undefined,
                                              .after = rhi::ResourceState::CopyDest};
            cmd->barrier(toClear);
            cmd->clearTextureFloat(target, kHostClear);
            const rhi::TextureBarrier toSource{.texture = target, .before = rhi::ResourceState::CopyDest,
                                               .after = rhi::ResourceState::CopySource};
            cmd->barrier(toSource);
        }
        Status st = graph.execute(*device, *cmd);
        cmd->end();
        CAUSTICS_CHECK(st);
        CAUSTICS_TRY(uint64_t fence, device->submit(cmd));
        return device->waitForFence(fence);
    };
    const rhi::TextureUsage usage = rhi::TextureUsage::Storage | rhi::TextureUsage::CopyDest | rhi::TextureUsage::CopySource;
    auto display = hostTarget(rhi::Format::RGBA8_UNORM, rhi::TextureUsage::CopyDest | rhi::TextureUsage::CopySource);
    auto target = hostTarget(rhi::Format::RGBA8_UNORM, usage);
    ASSERT_TRUE(display && target);
    ASSERT_TRUE(run(nullptr, display.value()).ok());
    Status st = run(target.value(), nullptr);
    ASSERT_TRUE(st.ok()) << st.message();
    const std::vector<uint8_t> expected = readTexture(display.value(), rhi::ResourceState::CopySource);
    const std::vector<uint8_t> got = readTexture(target.value(), rhi::ResourceState::CopySource);
    ASSERT_EQ(got.size(), expected.size());
    size_t differing = 0;
    for (size_t i = 0; i < got.size(); ++i) differing += got[i] != expected[i] ? 1 : 0;
    EXPECT_EQ(differing, 0u);
}

// The display path stores RGBA8 through a storage image and replaces the target: another format, or
// Add, is refused naming what it needs and where the other formats go.
TEST_F(OutputTarget, DisplayPathRefusesOtherFormatsAndAdd) {
    CausticsSettings s;
    s.causticsEnabled = false;
    auto standalone = CausticsModule::create(device, scene_, *gpuScene_, s);
    ASSERT_TRUE(standalone) << standalone.message();
    auto attempt = [&](rhi::Format format, OutputWrite write) -> Status {
        CAUSTICS_TRY(rhi::TextureHandle target, hostTarget(format, rhi::TextureUsage::Storage | rhi::TextureUsage::RenderTarget));
        rg::RenderGraph graph;
        FrameInputs in = viewOf(spotSphereCamera(), kTargetSize).inputs;
        in.outputTarget = target;
        in.outputWrite = write;
        CAUSTICS_TRY(FrameOutputs out, standalone.value()->addPasses(graph, in));
        (void)out;
        return okStatus();
    };
    Status half = attempt(rhi::Format::RGBA16_FLOAT, OutputWrite::Replace);
    ASSERT_FALSE(half.ok());
    EXPECT_NE(half.message().find("outputTarget 'host lighting' (RGBA16_FLOAT, 64x64)"), std::string::npos) << half.message();
    EXPECT_NE(half.message().find("RGBA8_UNORM with Storage usage"), std::string::npos) << half.message();
    EXPECT_NE(half.message().find("settings.causticsOnly"), std::string::npos) << half.message();
    Status add = attempt(rhi::Format::RGBA8_UNORM, OutputWrite::Add);
    ASSERT_FALSE(add.ok());
    EXPECT_NE(add.message().find("outputWrite Add"), std::string::npos) << add.message();
}

TEST_F(OutputTarget, IntegerFormatIsRefusedNamingTheFieldTheFormatAndWhatIsNeeded) {
    Status st = refusal(rhi::Format::RGBA32_UINT, rhi::TextureUsage::RenderTarget, kTargetSize);
    ASSERT_FALSE(st.ok());
    for (const char* part : {"outputTarget 'host lighting'", "RGBA32_UINT", "integer", "float or unorm colour format"})
        EXPECT_NE(st.message().find(part), std::string::npos) << part << " in: " << st.message();
}

TEST_F(OutputTarget, DepthFormatIsRefused) {
    Status st = refusal(rhi::Format::D32_FLOAT, rhi::TextureUsage::DepthStencil, kTargetSize);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.message().find("D32_FLOAT"), std::string::npos) << st.message();
    EXPECT_NE(st.message().find("depth format"), std::string::npos) << st.message();
}

TEST_F(OutputTarget, TwoChannelFormatIsRefusedRatherThanDroppingBlue) {
    Status st = refusal(rhi::Format::RG16_FLOAT, rhi::TextureUsage::RenderTarget, kTargetSize);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.message().find("RG16_FLOAT"), std::string::npos) << st.message();
    EXPECT_NE(st.message().find("fewer than three channels"), std::string::npos) << st.message();
}

TEST_F(OutputTarget, TargetWithoutRenderTargetUsageIsRefused) {
    Status st = refusal(rhi::Format::RGBA16_FLOAT, rhi::TextureUsage::Storage | rhi::TextureUsage::Sampled, kTargetSize);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.message().find("RGBA16_FLOAT"), std::string::npos) << st.message();
    EXPECT_NE(st.message().find("lacks RenderTarget usage"), std::string::npos) << st.message();
}

TEST_F(OutputTarget, TargetOfAnotherSizeIsRefusedWithBothSizes) {
    Status st = refusal(rhi::Format::RGBA16_FLOAT, rhi::TextureUsage::RenderTarget, kTargetSize / 2);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.message().find("is 32x32, the image (FrameInputs::width x height) is 64x64"), std::string::npos)
        << st.message();
}

TEST_F(OutputTarget, NegativeOrNonFiniteScaleIsRefused) {
    for (float scale : {-1.0f, std::nanf("")}) {
        Status st = refusal(rhi::Format::RGBA16_FLOAT, rhi::TextureUsage::RenderTarget, kTargetSize, scale);
        ASSERT_FALSE(st.ok());
        EXPECT_NE(st.message().find("outputScale"), std::string::npos) << st.message();
    }
}


}  // namespace
}  // namespace caustics::test
