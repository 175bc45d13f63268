// Culling: passes whose results nobody uses are removed unless they have side effects or feed an output.
#include <gtest/gtest.h>

#include "fake_memory_sizer.h"
#include "fake_rhi_objects.h"
#include "caustics/render_graph/render_graph.h"

namespace caustics::rg {
namespace {
using test::FakeMemorySizer;
using test::texDesc;

// Adds a pass that creates and writes a new texture; returns the written handle.
RgTexture producer(RenderGraph& g, const std::string& name, std::vector<RgTexture> inputs = {}) {
    RgTexture out;
    g.addPass(name, [&](PassBuilder& b) {
        for (RgTexture in : inputs) b.read(in, Access::SampledRead);
        out = b.write(b.createTexture(name + ".out", texDesc()), Access::StorageWrite);
        return [](PassContext&) {};
    });
    return out;
}

TEST(RenderGraphCulling, PassWhoseOutputNobodyReadsIsCulled) {
    RenderGraph g;
    producer(g, "unused");
    RgTexture kept = producer(g, "kept");
    g.markOutput(kept);
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    EXPECT_FALSE(g.plan()->passKept[0]);
    EXPECT_TRUE(g.plan()->passKept[1]);
    ASSERT_EQ(g.plan()->order.size(), 1u);
    EXPECT_EQ(g.plan()->order[0].pass, 1u);
}

TEST(RenderGraphCulling, SideEffectPassIsKeptWithoutReaders) {
    RenderGraph g;
    g.addPass("readback", [&](PassBuilder& b) {
        b.write(b.createTexture("t", texDesc()), Access::StorageWrite);
        b.setSideEffects();
        return [](PassContext&) {};
    });
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    EXPECT_TRUE(g.plan()->passKept[0]);
}

TEST(RenderGraphCulling, ChainEndingInOutputIsKeptWhole) {
    RenderGraph g;
    RgTexture a = producer(g, "a");
    RgTexture b = producer(g, "b", {a});
    producer(g, "dead", {a});
    RgTexture c = producer(g, "c", {b});
    g.markOutput(c);
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    EXPECT_EQ(g.plan()->passKept, (std::vector<bool>{true, true, false, true}));
}

TEST(RenderGraphCulling, ChainWithoutOutputIsCulledWhole) {
    RenderGraph g;
    RgTexture a = producer(g, "a");
    producer(g, "b", {a});
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    EXPECT_TRUE(g.plan()->order.empty());
}

TEST(RenderGraphCulling, WriterOfImportedOutputIsKept) {
    RenderGraph g;
    RgTexture host = g.importTexture("host", test::fakeTexture(), rhi::ResourceState::Common, rhi::ResourceState::Common);
    g.addPass("fill", [&](PassBuilder& b) {
        host = b.write(host, Access::CopyDest);
        return [](PassContext&) {};
    });
    g.markOutput(host);
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    EXPECT_TRUE(g.plan()->passKept[0]);
}

TEST(RenderGraphCulling, NullImportIsRejectedByName) {
    RenderGraph g;
    g.importTexture("hostColor", nullptr, rhi::ResourceState::Common, rhi::ResourceState::Common);
    Status s = g.compile(FakeMemorySizer());
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.message().find("hostColor"), std::string::npos);
}

TEST(RenderGraphCulling, EarlierWriterOfRewrittenOutputIsKept) {
    // A write may be partial, so the producer of the version it overwrites stays (conservative).
    RenderGraph g;
    RgTexture t;
    g.addPass("first", [&](PassBuilder& b) {
        t = b.write(b.createTexture("t", texDesc()), Access::RenderTarget);
        return [](PassContext&) {};
    });
    g.addPass("second", [&](PassBuilder& b) {
        t = b.write(t, Access::RenderTarget);
        return [](PassContext&) {};
    });
    g.markOutput(t);
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    EXPECT_EQ(g.plan()->passKept, (std::vector<bool>{true, true}));
}

}  // namespace
}  // namespace caustics::rg
