// Barrier placement: every hazard between kept passes gets exactly the transition it needs.
#include <gtest/gtest.h>

#include <optional>

#include "fake_memory_sizer.h"
#include "fake_rhi_objects.h"
#include "caustics/render_graph/render_graph.h"

namespace caustics::rg {
namespace {
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

// Two passes over one imported texture (kept by side effects) with the given accesses.
RgTexture twoPasses(RenderGraph& g, Access first, Access second, ResourceState initial = ResourceState::Common) {
    RgTexture t = g.importTexture("t", test::fakeTexture(), initial, ResourceState::Common);
    auto use = [&](const char* name, Access a) {
        g.addPass(name, [&](PassBuilder& b) {
            if (accessWrites(a)) t = b.write(t, a);
            else b.read(t, a);
            b.setSideEffects();
            return [](PassContext&) {};
        });
    };
    use("first", first);
    use("second", second);
    return t;
}

TEST(RenderGraphBarriers, ReadAfterStorageWriteTransitionsToShaderResource) {
    RenderGraph g;
    RgTexture t = twoPasses(g, Access::StorageWrite, Access::SampledRead);
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    auto b = barrierBefore(g, 1, t.index);
    ASSERT_TRUE(b);
    EXPECT_EQ(b->before, ResourceState::UnorderedAccess);
    EXPECT_EQ(b->after, ResourceState::ShaderResource);
}

TEST(RenderGraphBarriers, WriteAfterReadTransitionsToWriteState) {
    RenderGraph g;
    RgTexture t = twoPasses(g, Access::SampledRead, Access::StorageWrite, ResourceState::ShaderResource);
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    EXPECT_FALSE(barrierBefore(g, 0, t.index)) << "already in ShaderResource, nothing pending";
    auto b = barrierBefore(g, 1, t.index);
    ASSERT_TRUE(b);
    EXPECT_EQ(b->before, ResourceState::ShaderResource);
    EXPECT_EQ(b->after, ResourceState::UnorderedAccess);
}

TEST(RenderGraphBarriers, StorageWriteAfterStorageWriteGetsUavBarrier) {
    RenderGraph g;
    RgTexture t = twoPasses(g, Access::StorageWrite, Access::StorageReadWrite);
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    auto b = barrierBefore(g, 1, t.index);
    ASSERT_TRUE(b);
    EXPECT_EQ(b->before, ResourceState::UnorderedAccess);
    EXPECT_EQ(b->after, ResourceState::UnorderedAccess);
}

TEST(RenderGraphBarriers, ReadAfterReadInSameStateNeedsNoBarrier) {
    RenderGraph g;
    RgTexture t = twoPasses(g, Access::SampledRead, Access::SampledRead, ResourceState::ShaderResource);
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    EXPECT_FALSE(barrierBefore(g, 1, t.index));
}

TEST(RenderGraphBarriers, RenderTargetThenSampledChangesLayout) {
    RenderGraph g;
    RgTexture t;
    g.addPass("draw", [&](PassBuilder& b) {
        t = b.write(b.createTexture("color", texDesc()), Access::RenderTarget);
        return [](PassContext&) {};
    });
    g.addPass("blur", [&](PassBuilder& b) {
        b.read(t, Access::SampledRead);
        b.setSideEffects();
        return [](PassContext&) {};
    });
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    auto first = barrierBefore(g, 0, t.index);
    ASSERT_TRUE(first);
    EXPECT_EQ(first->before, ResourceState::Undefined);
    EXPECT_EQ(first->after, ResourceState::RenderTarget);
    EXPECT_TRUE(first->activation);
    auto second = barrierBefore(g, 1, t.index);
    ASSERT_TRUE(second);
    EXPECT_EQ(second->before, ResourceState::RenderTarget);
    EXPECT_EQ(second->after, ResourceState::ShaderResource);
}

TEST(RenderGraphBarriers, TransientUsageFlagsFollowDeclaredAccesses) {
    RenderGraph g;
    RgTexture t;
    g.addPass("draw", [&](PassBuilder& b) {
        t = b.write(b.createTexture("color", texDesc().setUsage(rhi::TextureUsage::None)), Access::RenderTarget);
        return [](PassContext&) {};
    });
    g.addPass("read", [&](PassBuilder& b) {
        b.read(t, Access::SampledRead);
        b.setSideEffects();
        return [](PassContext&) {};
    });
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    EXPECT_EQ(g.plan()->textureDescs[t.index].usage, rhi::TextureUsage::RenderTarget | rhi::TextureUsage::Sampled);
}

TEST(RenderGraphBarriers, AccelStructBuildThenTraceGetsBuildToReadBarrier) {
    RenderGraph g;
    RgAccelStruct tlas = g.importAccelStruct("tlas", test::fakeAccelStruct(), ResourceState::AccelStructRead,
                                             ResourceState::AccelStructRead);
    RgBuffer instances = g.importBuffer("instances", test::fakeBuffer(), ResourceState::CopyDest,
                                       ResourceState::CopyDest);
    g.addPass("buildTlas", [&](PassBuilder& b) {
        b.read(instances, Access::AccelStructBuildInput);
        tlas = b.write(tlas, Access::AccelStructBuild);
        return [](PassContext&) {};
    });
    g.addPass("trace", [&](PassBuilder& b) {
        b.read(tlas, Access::AccelStructTrace);
        b.setSideEffects();
        return [](PassContext&) {};
    });
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    auto input = barrierBefore(g, 0, instances.index);
    ASSERT_TRUE(input);
    EXPECT_EQ(input->after, ResourceState::AccelStructBuildInput);
    auto build = barrierBefore(g, 0, tlas.index);
    ASSERT_TRUE(build) << "a rebuild must wait for earlier traces (write after read)";
    EXPECT_EQ(build->after, ResourceState::AccelStructWrite);
    auto trace = barrierBefore(g, 1, tlas.index);
    ASSERT_TRUE(trace);
    EXPECT_EQ(trace->kind, ResourceKind::AccelStruct);
    EXPECT_EQ(trace->before, ResourceState::AccelStructWrite);
    EXPECT_EQ(trace->after, ResourceState::AccelStructRead);
}

TEST(RenderGraphBarriers, ImportedResourceEndsInRequestedFinalState) {
    RenderGraph g;
    RgTexture out = g.importTexture("output", test::fakeTexture(), ResourceState::Common, ResourceState::CopySource);
    g.addPass("write", [&](PassBuilder& b) {
        out = b.write(out, Access::StorageWrite);
        return [](PassContext&) {};
    });
    g.markOutput(out);
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    const auto& finals = g.plan()->finalBarriers;
    ASSERT_EQ(finals.size(), 1u);
    EXPECT_EQ(finals[0].resource, out.index);
    EXPECT_EQ(finals[0].before, ResourceState::UnorderedAccess);
    EXPECT_EQ(finals[0].after, ResourceState::CopySource);
}

TEST(RenderGraphBarriers, UnusedImportStillEndsInRequestedFinalState) {
    RenderGraph g;
    RgTexture t = g.importTexture("idle", test::fakeTexture(), ResourceState::RenderTarget, ResourceState::ShaderResource);
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    const auto& finals = g.plan()->finalBarriers;
    ASSERT_EQ(finals.size(), 1u);
    EXPECT_EQ(finals[0].resource, t.index);
    EXPECT_EQ(finals[0].before, ResourceState::RenderTarget);
    EXPECT_EQ(finals[0].after, ResourceState::ShaderResource);
}

TEST(RenderGraphBarriers, TransientOutputEndsInRequestedState) {
    RenderGraph g;
    RgTexture t;
    g.addPass("draw", [&](PassBuilder& b) {
        t = b.write(b.createTexture("exported", texDesc()), Access::RenderTarget);
        return [](PassContext&) {};
    });
    g.markOutput(t, ResourceState::ShaderResource);
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    const auto& finals = g.plan()->finalBarriers;
    ASSERT_EQ(finals.size(), 1u);
    EXPECT_EQ(finals[0].before, ResourceState::RenderTarget);
    EXPECT_EQ(finals[0].after, ResourceState::ShaderResource);
}

TEST(RenderGraphBarriers, ImportedFirstUseStartsFromHostState) {
    RenderGraph g;
    RgTexture t = twoPasses(g, Access::SampledRead, Access::SampledRead, ResourceState::CopyDest);
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    auto b = barrierBefore(g, 0, t.index);
    ASSERT_TRUE(b);
    EXPECT_EQ(b->before, ResourceState::CopyDest);
    EXPECT_EQ(b->after, ResourceState::ShaderResource);
    EXPECT_FALSE(b->activation);
}

}  // namespace
}  // namespace caustics::rg
