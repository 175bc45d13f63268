// A 4-pass graph (compute fill -> raster draw -> compute blur -> copy to an imported readback buffer)
// must produce exactly the image of the same passes recorded by hand with explicit barriers, with no
// validation message (the GpuTest fixture fails on any warning or error, synchronization included).
#include <gtest/gtest.h>

#include <cstring>

#include "four_pass_recording.h"
#include "gpu_test.h"
#include "caustics/render_graph/render_graph.h"

namespace caustics::test {
namespace {
using namespace rhi;
using rg::Access;
using rg::PassBuilder;
using rg::PassContext;
using rg::RgBuffer;
using rg::RgTexture;

constexpr uint64_t kImageBytes = uint64_t(kImageSize) * kImageSize * 4;

class RenderGraphGpuTest : public GpuTest {
protected:
    BufferHandle makeReadback() {
        auto b = device->createBuffer(BufferDesc()
                                          .setByteSize(kImageBytes)
                                          .setUsage(BufferUsage::CopyDest)
                                          .setMemory(MemoryType::Readback)
                                          .setDebugName("readback"));
        EXPECT_TRUE(b.ok()) << (b.ok() ? "" : b.message());
        return b.ok() ? b.value() : nullptr;
    }

    std::vector<uint8_t> read(const BufferHandle& readback) {
        std::vector<uint8_t> bytes(kImageBytes);
        auto s = device->readBuffer(readback, bytes.data(), kImageBytes);
        EXPECT_TRUE(s.ok()) << (s.ok() ? "" : s.message());
        return bytes;
    }

    // Records with `record`, submits and waits.
    void run(const std::function<Status(ICommandList&)>& record) {
        auto cmd = device->createCommandList();
        ASSERT_TRUE(cmd.ok()) << cmd.message();
        cmd.value()->begin();
        Status recorded = record(*cmd.value());
        cmd.value()->end();
        ASSERT_TRUE(recorded.ok()) << recorded.message();
        auto fence = device->submit(cmd.value());
        ASSERT_TRUE(fence.ok()) << fence.message();
        auto waited = device->waitForFence(fence.value());
        ASSERT_TRUE(waited.ok()) << waited.message();
    }

    std::vector<uint8_t> renderByHand(const FourPassPipelines& p) {
        TextureDesc desc = TextureDesc().setSize(kImageSize, kImageSize).setFormat(kImageFormat);
        auto pattern = device->createTexture(TextureDesc(desc).setUsage(TextureUsage::Storage | TextureUsage::Sampled).setDebugName("pattern"));
        auto drawn = device->createTexture(TextureDesc(desc).setUsage(TextureUsage::RenderTarget | TextureUsage::Sampled).setDebugName("drawn"));
        auto blurred = device->createTexture(TextureDesc(desc).setUsage(TextureUsage::Storage | TextureUsage::CopySource).setDebugName("blurred"));
        EXPECT_TRUE(pattern.ok() && drawn.ok() && blurred.ok());
        if (!pattern.ok() || !drawn.ok() || !blurred.ok()) return {};
        BufferHandle readback = makeReadback();
        std::vector<BindingSetHandle> keep;
        using S = ResourceState;
        run([&](ICommandList& cmd) -> Status {
            cmd.barrier(TextureBarrier{pattern.value(), S::Undefined, S::UnorderedAccess});
            CAUSTICS_CHECK(recordFill(*device, cmd, p, pattern.value(), keep));
            cmd.barriers(std::vector<TextureBarrier>{{pattern.value(), S::UnorderedAccess, S::ShaderResource},
                                                     {drawn.value(), S::Undefined, S::RenderTarget}},
                         {});
            CAUSTICS_CHECK(recordDraw(*device, cmd, p, pattern.value(), drawn.value(), keep));
            cmd.barriers(std::vector<TextureBarrier>{{drawn.value(), S::RenderTarget, S::ShaderResource},
                                                     {blurred.value(), S::Undefined, S::UnorderedAccess}},
                         {});
            CAUSTICS_CHECK(recordBlur(*device, cmd, p, drawn.value(), blurred.value(), keep));
            cmd.barrier(TextureBarrier{blurred.value(), S::UnorderedAccess, S::CopySource});
            cmd.barrier(BufferBarrier{readback, S::Undefined, S::CopyDest});
            recordCopy(cmd, blurred.value(), readback);
            cmd.barrier(BufferBarrier{readback, S::CopyDest, S::Common});
            return okStatus();
        });
        return read(readback);
    }

    // One frame of the graph: declares the four passes and executes them.
    std::vector<uint8_t> renderWithGraph(rg::RenderGraph& graph, const FourPassPipelines& p) {
        BufferHandle readback = makeReadback();
        std::vector<BindingSetHandle> keep;
        TextureDesc desc = TextureDesc().setSize(kImageSize, kImageSize).setFormat(kImageFormat);
        IDevice& dev = *device;
        graph.reset();
        RgBuffer out = graph.importBuffer("readback", readback, ResourceState::Undefined, ResourceState::Common);
        RgTexture pattern, drawn, blurred;
        graph.addPass("fill", [&](PassBuilder& b) {
            pattern = b.write(b.createTexture("pattern", desc), Access::StorageWrite);
            return [&, pattern](PassContext& ctx) { EXPECT_TRUE(recordFill(dev, ctx.cmd(), p, ctx.texture(pattern), keep).ok()); };
        });
        graph.addPass("draw", [&](PassBuilder& b) {
            b.read(pattern, Access::SampledRead);
            drawn = b.write(b.createTexture("drawn", desc), Access::RenderTarget);
            return [&, pattern, drawn](PassContext& ctx) {
                EXPECT_TRUE(recordDraw(dev, ctx.cmd(), p, ctx.texture(pattern), ctx.texture(drawn), keep).ok());
            };
        });
        graph.addPass("blur", [&](PassBuilder& b) {
            b.read(drawn, Access::SampledRead);
            blurred = b.write(b.createTexture("blurred", desc), Access::StorageWrite);
            return [&, drawn, blurred](PassContext& ctx) {
                EXPECT_TRUE(recordBlur(dev, ctx.cmd(), p, ctx.texture(drawn), ctx.texture(blurred), keep).ok());
            };
        });
        graph.addPass("copy", [&](PassBuilder& b) {
            b.read(blurred, Access::CopySource);
            out = b.write(out, Access::CopyDest);
            return [blurred, out](PassContext& ctx) { recordCopy(ctx.cmd(), ctx.texture(blurred), ctx.buffer(out)); };
        });
        graph.markOutput(out);
        run([&](ICommandList& cmd) { return graph.execute(dev, cmd); });
        graph.collectTimings(dev);
        return read(readback);
    }
};

TEST_F(RenderGraphGpuTest, FourPassGraphMatchesHandRecordedPasses) {
    auto pipelines = makeFourPassPipelines(*device);
    ASSERT_TRUE(pipelines.ok()) << pipelines.message();
    std::vector<uint8_t> expected = renderByHand(pipelines.value());
    ASSERT_EQ(expected.size(), kImageBytes);

    rg::RenderGraph graph;
    // Two frames: the second reuses the first frame's transients (and aliased heap memory).
    for (int frame = 0; frame < 2; ++frame) {
        std::vector<uint8_t> got = renderWithGraph(graph, pipelines.value());
        ASSERT_EQ(got.size(), kImageBytes);
        // Exact: the same shaders run on the same inputs, only the barriers come from the graph.
        EXPECT_EQ(std::memcmp(got.data(), expected.data(), kImageBytes), 0) << "frame " << frame;
    }
    std::printf("%s", graph.printText().c_str());

    // The image must show the triangle (pattern) over the clear colour, so a blank result cannot pass.
    auto pixel = [&](uint32_t x, uint32_t y) { return &expected[(size_t(y) * kImageSize + x) * 4]; };
    const uint8_t* corner = pixel(0, 0);
    const uint8_t* centre = pixel(kImageSize / 2, kImageSize / 2);
    EXPECT_NEAR(corner[0], 26, 1) << "clear colour 0.1 in red (unorm8 rounding)";
    EXPECT_NE(std::memcmp(corner, centre, 4), 0) << "the triangle covers the centre";
}

}  // namespace
}  // namespace caustics::test
