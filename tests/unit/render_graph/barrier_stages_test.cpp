// The work on either side of each barrier (docs/embedding.md "Barriers"): a barrier waits only for the
// kind of pass that produced the resource and blocks only the kind that consumes it, instead of every
// shader stage (or ALL_COMMANDS at a transient's first use).
#include <gtest/gtest.h>

#include <optional>

#include "recording_device.h"
#include "caustics/render_graph/render_graph.h"

namespace caustics::rg {
namespace {
using rhi::PipelineStages;
using rhi::ResourceState;
using test::FakeMemorySizer;
using test::texDesc;

std::optional<PlannedBarrier> barrierBefore(const RenderGraph& g, uint32_t pass, uint32_t resource) {
    const PlannedPass* planned = g.plan()->findPass(pass);
    if (!planned) return std::nullopt;
    for (const PlannedBarrier& b : planned->barriers)
        if (b.resource == resource) return b;
    return std::nullopt;
}

rhi::BufferDesc bufferDesc() { return rhi::BufferDesc().setByteSize(256); }

// producer writes a transient, consumer (declared `consumerWork`, kept by side effects) reads it.
template <typename Produce, typename Consume>
void chain(RenderGraph& g, Produce produce, Consume consume) {
    g.addPass("producer", [&](PassBuilder& b) {
        produce(b);
        return [](PassContext&) {};
    });
    g.addPass("consumer", [&](PassBuilder& b) {
        consume(b);
        b.setSideEffects();
        return [](PassContext&) {};
    });
}

TEST(RenderGraphBarrierStages, ComputeThenRayTracingWaitsForComputeAndBlocksRayTracing) {
    RenderGraph g;
    RgBuffer photons;
    chain(
        g,
        [&](PassBuilder& b) {
            b.setStages(PipelineStages::Compute);
            photons = b.write(b.createBuffer("photons", bufferDesc()), Access::StorageWrite);
        },
        [&](PassBuilder& b) {
            b.setStages(PipelineStages::RayTracing);
            b.read(photons, Access::SampledRead);
        });
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    auto barrier = barrierBefore(g, 1, photons.index);
    ASSERT_TRUE(barrier);
    EXPECT_EQ(barrier->before, ResourceState::UnorderedAccess);
    EXPECT_EQ(barrier->after, ResourceState::ShaderResource);
    EXPECT_EQ(barrier->srcStages, PipelineStages::Compute);
    EXPECT_EQ(barrier->dstStages, PipelineStages::RayTracing);
}

TEST(RenderGraphBarrierStages, RasterThenComputeWaitsForTheDrawInferredFromItsAttachment) {
    RenderGraph g;
    RgTexture color;
    chain(
        g, [&](PassBuilder& b) { color = b.write(b.createTexture("color", texDesc()), Access::RenderTarget); },
        [&](PassBuilder& b) {
            b.setStages(PipelineStages::Compute);
            b.read(color, Access::SampledRead);
        });
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    auto barrier = barrierBefore(g, 1, color.index);
    ASSERT_TRUE(barrier);
    EXPECT_EQ(barrier->before, ResourceState::RenderTarget);
    EXPECT_EQ(barrier->srcStages, PipelineStages::Raster) << "a pass with a colour attachment draws";
    EXPECT_EQ(barrier->dstStages, PipelineStages::Compute);
}

TEST(RenderGraphBarrierStages, CopyThenComputeWaitsForTheCopyInferredFromItsAccesses) {
    RenderGraph g;
    RgBuffer constants;
    chain(
        g, [&](PassBuilder& b) { constants = b.write(b.createBuffer("constants", bufferDesc()), Access::CopyDest); },
        [&](PassBuilder& b) {
            b.setStages(PipelineStages::Compute);
            b.read(constants, Access::StorageRead);
        });
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    auto barrier = barrierBefore(g, 1, constants.index);
    ASSERT_TRUE(barrier);
    EXPECT_EQ(barrier->before, ResourceState::CopyDest);
    EXPECT_EQ(barrier->srcStages, PipelineStages::Copy) << "copy accesses alone: a copy pass";
    EXPECT_EQ(barrier->dstStages, PipelineStages::Compute);
}

TEST(RenderGraphBarrierStages, ShaderAccessesOfAPassOfUnknownKindKeepEveryStage) {
    RenderGraph g;
    RgBuffer data;
    chain(
        g, [&](PassBuilder& b) { data = b.write(b.createBuffer("data", bufferDesc()), Access::StorageWrite); },
        [&](PassBuilder& b) {
            b.setStages(PipelineStages::Compute);
            b.read(data, Access::SampledRead);
        });
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    auto barrier = barrierBefore(g, 1, data.index);
    ASSERT_TRUE(barrier);
    EXPECT_EQ(barrier->srcStages, PipelineStages::None) << "a storage write could come from any shader stage";
    EXPECT_EQ(barrier->dstStages, PipelineStages::Compute);
}

TEST(RenderGraphBarrierStages, EveryReaderBetweenTwoBarriersIsInTheFirstsDestinationAndTheSecondsSource) {
    RenderGraph g;
    RgTexture t = g.importTexture("t", test::fakeTexture(), ResourceState::UnorderedAccess, ResourceState::Common);
    auto pass = [&](const char* name, PipelineStages work, Access access) {
        g.addPass(name, [&, work, access](PassBuilder& b) {
            b.setStages(work);
            if (accessWrites(access)) t = b.write(t, access);
            else b.read(t, access);
            b.setSideEffects();
            return [](PassContext&) {};
        });
    };
    pass("write", PipelineStages::Compute, Access::StorageWrite);
    pass("read by compute", PipelineStages::Compute, Access::SampledRead);
    pass("read by rays", PipelineStages::RayTracing, Access::SampledRead);   // same state: no barrier
    pass("write again", PipelineStages::Compute, Access::StorageWrite);
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    auto raw = barrierBefore(g, 1, t.index);
    ASSERT_TRUE(raw);
    EXPECT_EQ(raw->dstStages, PipelineStages::Compute | PipelineStages::RayTracing)
        << "the one barrier into ShaderResource serves both readers";
    EXPECT_FALSE(barrierBefore(g, 2, t.index));
    auto war = barrierBefore(g, 3, t.index);
    ASSERT_TRUE(war);
    EXPECT_EQ(war->srcStages, PipelineStages::Compute | PipelineStages::RayTracing);
    EXPECT_EQ(war->dstStages, PipelineStages::Compute);
}

TEST(RenderGraphBarrierStages, HostSidesOfAnImportKeepEveryStage) {
    RenderGraph g;
    RgTexture out = g.importTexture("out", test::fakeTexture(), ResourceState::ShaderResource,
                                    ResourceState::ShaderResource);
    g.addPass("write", [&](PassBuilder& b) {
        b.setStages(PipelineStages::Compute);
        out = b.write(out, Access::StorageWrite);
        return [](PassContext&) {};
    });
    g.markOutput(out);
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    auto first = barrierBefore(g, 0, out.index);
    ASSERT_TRUE(first);
    EXPECT_EQ(first->srcStages, PipelineStages::None) << "the host's earlier work is of no known kind";
    EXPECT_EQ(first->dstStages, PipelineStages::Compute);
    ASSERT_EQ(g.plan()->finalBarriers.size(), 1u);
    EXPECT_EQ(g.plan()->finalBarriers[0].srcStages, PipelineStages::Compute);
    EXPECT_EQ(g.plan()->finalBarriers[0].dstStages, PipelineStages::None) << "the host's later work";
}

// One frame: a draw into a transient, a compute pass reading it into an imported output.
void drawThenCompute(RenderGraph& g, const rhi::TextureHandle& host, PipelineStages secondWork) {
    RgTexture out = g.importTexture("out", host, ResourceState::UnorderedAccess, ResourceState::UnorderedAccess);
    RgTexture color;
    g.addPass("draw", [&](PassBuilder& b) {
        color = b.write(b.createTexture("color", texDesc()), Access::RenderTarget);
        return [](PassContext&) {};
    });
    g.addPass("second", [&](PassBuilder& b) {
        b.setStages(secondWork);
        b.read(color, Access::SampledRead);
        out = b.write(out, Access::StorageWrite);
        return [](PassContext&) {};
    });
    g.markOutput(out);
}

TEST(RenderGraphBarrierStages, FirstUseOfATransientWaitsForTheWorkOfEveryTransientUserNotAllCommands) {
    test::RecordingDevice device;
    RenderGraph g;
    const rhi::TextureHandle host = test::fakeTexture();
    drawThenCompute(g, host, PipelineStages::Compute);
    test::RecordingCommandList frame1;
    ASSERT_TRUE(g.execute(device, frame1).ok());
    ASSERT_FALSE(frame1.textureBarriers.empty());
    const rhi::TextureBarrier& activation = frame1.textureBarriers.front();
    EXPECT_EQ(activation.before, ResourceState::Undefined);
    EXPECT_TRUE(activation.aliasing) << "the memory may hold an earlier frame's transient";
    EXPECT_EQ(activation.beforeStages, PipelineStages::Raster | PipelineStages::Compute);
    EXPECT_EQ(activation.afterStages, PipelineStages::Raster);

    // The next frame's passes are all raster and compute again, but a frame of unknown work in between
    // widens every later activation to all stages: the earlier frame may still be in flight.
    g.reset();
    drawThenCompute(g, host, PipelineStages::None);
    test::RecordingCommandList frame2;
    ASSERT_TRUE(g.execute(device, frame2).ok());
    EXPECT_EQ(frame2.textureBarriers.front().beforeStages, PipelineStages::None);
    g.reset();
    drawThenCompute(g, host, PipelineStages::Compute);
    test::RecordingCommandList frame3;
    ASSERT_TRUE(g.execute(device, frame3).ok());
    EXPECT_EQ(frame3.textureBarriers.front().beforeStages, PipelineStages::None);
}

TEST(RenderGraphBarrierStages, PrintedBarriersNameTheirStages) {
    RenderGraph g;
    RgBuffer photons;
    chain(
        g,
        [&](PassBuilder& b) {
            b.setStages(PipelineStages::Compute);
            photons = b.write(b.createBuffer("photons", bufferDesc()), Access::StorageWrite);
        },
        [&](PassBuilder& b) {
            b.setStages(PipelineStages::RayTracing);
            b.read(photons, Access::SampledRead);
        });
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    const std::string text = g.printText();
    EXPECT_NE(text.find("buffer 'photons' UnorderedAccess -> ShaderResource [Compute -> RayTracing]"), std::string::npos)
        << text;
}

}  // namespace
}  // namespace caustics::rg
