// Ordering, lifetimes and setup validation.
#include <gtest/gtest.h>

#include "fake_memory_sizer.h"
#include "fake_rhi_objects.h"
#include "caustics/render_graph/render_graph.h"

namespace caustics::rg {
namespace {
using test::FakeMemorySizer;
using test::texDesc;

TEST(RenderGraphOrdering, KeptPassesRunInDeclarationOrder) {
    RenderGraph g;
    RgTexture a, b;
    g.addPass("makeA", [&](PassBuilder& pb) {
        a = pb.write(pb.createTexture("a", texDesc()), Access::StorageWrite);
        return [](PassContext&) {};
    });
    g.addPass("makeB", [&](PassBuilder& pb) {
        b = pb.write(pb.createTexture("b", texDesc()), Access::StorageWrite);
        return [](PassContext&) {};
    });
    g.addPass("combine", [&](PassBuilder& pb) {
        pb.read(b);
        pb.read(a);
        pb.setSideEffects();
        return [](PassContext&) {};
    });
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    const CompiledPlan& plan = *g.plan();
    ASSERT_EQ(plan.order.size(), 3u);
    for (uint32_t i = 0; i < 3; ++i) EXPECT_EQ(plan.order[i].pass, i);
}

TEST(RenderGraphOrdering, EveryDependencyHasProducerBeforeConsumer) {
    RenderGraph g;
    RgTexture t;
    g.addPass("write", [&](PassBuilder& b) {
        t = b.write(b.createTexture("t", texDesc()), Access::StorageWrite);
        return [](PassContext&) {};
    });
    g.addPass("modify", [&](PassBuilder& b) {
        t = b.write(t, Access::StorageReadWrite);
        return [](PassContext&) {};
    });
    g.addPass("read", [&](PassBuilder& b) {
        b.read(t);
        b.setSideEffects();
        return [](PassContext&) {};
    });
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    const auto& deps = g.plan()->dependencies;
    ASSERT_EQ(deps.size(), 2u);
    EXPECT_EQ(deps[0].producer, 0u);
    EXPECT_EQ(deps[0].consumer, 1u);
    EXPECT_EQ(deps[1].producer, 1u);
    EXPECT_EQ(deps[1].consumer, 2u);
}

TEST(RenderGraphOrdering, LifetimeSpansFirstToLastUse) {
    RenderGraph g;
    RgTexture t;
    g.addPass("write", [&](PassBuilder& b) {
        t = b.write(b.createTexture("t", texDesc()), Access::StorageWrite);
        return [](PassContext&) {};
    });
    g.addPass("other", [&](PassBuilder& b) {
        b.write(b.createTexture("u", texDesc()), Access::StorageWrite);
        b.setSideEffects();
        return [](PassContext&) {};
    });
    g.addPass("read", [&](PassBuilder& b) {
        b.read(t);
        b.setSideEffects();
        return [](PassContext&) {};
    });
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    EXPECT_EQ(g.plan()->lifetimes[t.index].first, 0u);
    EXPECT_EQ(g.plan()->lifetimes[t.index].last, 2u);
}

TEST(RenderGraphValidation, ReadOfStaleVersionIsRejected) {
    RenderGraph g;
    RgTexture v1, v2;
    g.addPass("w1", [&](PassBuilder& b) {
        v1 = b.write(b.createTexture("t", texDesc()), Access::StorageWrite);
        return [](PassContext&) {};
    });
    g.addPass("w2", [&](PassBuilder& b) {
        v2 = b.write(v1, Access::StorageReadWrite);
        return [](PassContext&) {};
    });
    g.addPass("staleRead", [&](PassBuilder& b) {
        b.read(v1);
        b.setSideEffects();
        return [](PassContext&) {};
    });
    Status s = g.compile(FakeMemorySizer());
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.message().find("staleRead"), std::string::npos) << s.message();
    EXPECT_NE(s.message().find("stale"), std::string::npos) << s.message();
}

TEST(RenderGraphValidation, ReadOfNeverWrittenTransientIsRejected) {
    RenderGraph g;
    g.addPass("reader", [&](PassBuilder& b) {
        b.read(b.createTexture("empty", texDesc()));
        b.setSideEffects();
        return [](PassContext&) {};
    });
    Status s = g.compile(FakeMemorySizer());
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.message().find("empty"), std::string::npos) << s.message();
}

TEST(RenderGraphValidation, WrittenResourceInTwoStatesInOnePassIsRejected) {
    RenderGraph g;
    RgTexture host = g.importTexture("host", test::fakeTexture(), rhi::ResourceState::Common, rhi::ResourceState::Common);
    g.addPass("conflict", [&](PassBuilder& b) {
        b.read(host, Access::SampledRead);
        b.write(host, Access::StorageWrite);
        b.setSideEffects();
        return [](PassContext&) {};
    });
    Status s = g.compile(FakeMemorySizer());
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.message().find("conflict"), std::string::npos) << s.message();
}

TEST(RenderGraphValidation, AccessInvalidForKindIsRejected) {
    RenderGraph g;
    g.addPass("bad", [&](PassBuilder& b) {
        b.write(b.createBuffer("buf", test::bufDesc()), Access::RenderTarget);
        b.setSideEffects();
        return [](PassContext&) {};
    });
    Status s = g.compile(FakeMemorySizer());
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.message().find("RenderTarget"), std::string::npos) << s.message();
}

}  // namespace
}  // namespace caustics::rg
