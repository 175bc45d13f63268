// execute() against a recording test double: what it records, how it resolves resources, reuse of
// transients across frames and per-pass timings.
#include <gtest/gtest.h>

#include <algorithm>

#include "recording_device.h"
#include "caustics/render_graph/render_graph.h"

namespace caustics::rg {
namespace {
using rhi::ResourceState;
using test::RecordingCommandList;
using test::RecordingDevice;
using test::texDesc;

struct Frame {
    RgTexture tmp, out;
};

// fill (storage write tmp) -> copy (tmp -> imported output).
Frame declareFrame(RenderGraph& g, const rhi::TextureHandle& host) {
    Frame f;
    f.out = g.importTexture("output", host, ResourceState::Common, ResourceState::ShaderResource);
    g.addPass("fill", [&](PassBuilder& b) {
        f.tmp = b.write(b.createTexture("tmp", texDesc()), Access::StorageWrite);
        return [](PassContext& ctx) { ctx.cmd().dispatch(1); };
    });
    g.addPass("copy", [&](PassBuilder& b) {
        b.read(f.tmp, Access::CopySource);
        f.out = b.write(f.out, Access::CopyDest);
        return [](PassContext& ctx) { ctx.cmd().dispatch(1); };
    });
    g.markOutput(f.out);
    return f;
}

size_t indexOf(const std::vector<std::string>& calls, const std::string& call) {
    return size_t(std::find(calls.begin(), calls.end(), call) - calls.begin());
}

TEST(RenderGraphExecute, BarriersAreRecordedBeforeTheirPass) {
    RecordingDevice device;
    RecordingCommandList cmd;
    RenderGraph g;
    declareFrame(g, std::make_shared<test::FakeTexture>(texDesc().setDebugName("output")));
    ASSERT_TRUE(g.execute(device, cmd).ok());
    const auto& c = cmd.calls;
    size_t activate = indexOf(c, "barrier tmp Undefined->UnorderedAccess");
    size_t fill = indexOf(c, "begin fill");
    size_t toCopySource = indexOf(c, "barrier tmp UnorderedAccess->CopySource");
    size_t outToCopyDest = indexOf(c, "barrier output Common->CopyDest");
    size_t copy = indexOf(c, "begin copy");
    size_t final = indexOf(c, "barrier output CopyDest->ShaderResource");
    ASSERT_LT(final, c.size());
    EXPECT_LT(activate, fill);
    EXPECT_LT(fill, toCopySource);
    EXPECT_LT(toCopySource, copy);
    EXPECT_LT(outToCopyDest, copy);
    EXPECT_LT(copy, final);
}

TEST(RenderGraphExecute, DeclaredResourceResolvesToPhysicalObject) {
    RecordingDevice device;
    RecordingCommandList cmd;
    RenderGraph g;
    rhi::TextureHandle host = std::make_shared<test::FakeTexture>();
    RgTexture out = g.importTexture("output", host, ResourceState::Common, ResourceState::Common);
    rhi::TextureHandle seen;
    g.addPass("write", [&](PassBuilder& b) {
        RgTexture w = b.write(out, Access::StorageWrite);
        return [&, w](PassContext& ctx) { seen = ctx.texture(w); };
    });
    g.markOutput(out);
    ASSERT_TRUE(g.execute(device, cmd).ok());
    EXPECT_EQ(seen, host);
}

TEST(RenderGraphExecute, UndeclaredResourceIsRefusedWithPassAndResourceNamed) {
    RecordingDevice device;
    RecordingCommandList cmd;
    RenderGraph g;
    RgTexture secret = g.importTexture("secret", test::fakeTexture(), ResourceState::Common, ResourceState::Common);
    rhi::TextureHandle seen = test::fakeTexture();
    g.addPass("sneaky", [&](PassBuilder& b) {
        b.setSideEffects();
        return [&](PassContext& ctx) { seen = ctx.texture(secret); };
    });
    setLogCallback([](LogLevel, std::string_view) {});   // the error is expected; keep the test output clean
    Status s = g.execute(device, cmd);
    setLogCallback(nullptr);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(seen, nullptr);
    EXPECT_NE(s.message().find("sneaky"), std::string::npos) << s.message();
    EXPECT_NE(s.message().find("secret"), std::string::npos) << s.message();
}

TEST(RenderGraphExecute, TransientsAreReusedAcrossFramesWhenDescsMatch) {
    RecordingDevice device;
    RenderGraph g;
    rhi::TextureHandle host = test::fakeTexture();
    for (int frame = 0; frame < 3; ++frame) {
        RecordingCommandList cmd;
        g.reset();
        declareFrame(g, host);
        ASSERT_TRUE(g.execute(device, cmd).ok());
    }
    EXPECT_EQ(device.texturesCreated, 1);
    EXPECT_EQ(device.heapsCreated, 1);
}

TEST(RenderGraphExecute, TransientIsBoundAtItsPlannedHeapOffset) {
    RecordingDevice device;
    RecordingCommandList cmd;
    RenderGraph g;
    Frame f = declareFrame(g, test::fakeTexture());
    ASSERT_TRUE(g.execute(device, cmd).ok());
    rhi::TextureHandle tmp = g.texture(f.tmp);
    ASSERT_TRUE(tmp);
    EXPECT_TRUE(tmp->desc().isVirtual);
    ASSERT_TRUE(device.boundOffsets.count(tmp.get()));
    EXPECT_EQ(device.boundOffsets[tmp.get()], *g.plan()->heapOffset[f.tmp.index]);
}

TEST(RenderGraphExecute, PassTimesAreMeasuredAndPrinted) {
    RecordingDevice device;   // every timed pass reads back exactly 1 ms
    RecordingCommandList cmd;
    RenderGraph g;
    declareFrame(g, test::fakeTexture());
    ASSERT_TRUE(g.execute(device, cmd).ok());
    g.collectTimings(device);
    ASSERT_TRUE(g.passTimeMs("fill"));
    EXPECT_DOUBLE_EQ(*g.passTimeMs("fill"), 1.0);
    EXPECT_NE(g.printText().find("'fill' 1.000 ms"), std::string::npos) << g.printText();
    EXPECT_NE(g.printGraphviz().find("fill\\n1.000 ms"), std::string::npos) << g.printGraphviz();
}

// A list that records no timestamps (a host's, wrapped with allowTimestamps = false): the graph
// creates no query pool on the device and records no timestamp; per-pass times stay empty. A later
// list that does record them gets the pool then.
TEST(RenderGraphExecute, ListWithoutTimestampsGetsNoQueryPool) {
    RecordingDevice device;
    RecordingCommandList untimed;
    untimed.timestamps = false;
    RenderGraph g;
    declareFrame(g, test::fakeTexture());
    ASSERT_TRUE(g.execute(device, untimed).ok());
    EXPECT_EQ(device.timestampPoolsCreated, 0);
    EXPECT_EQ(std::count_if(untimed.calls.begin(), untimed.calls.end(),
                            [](const std::string& c) { return c.rfind("timestamp", 0) == 0; }),
              0);
    g.collectTimings(device);
    EXPECT_FALSE(g.passTimeMs("fill"));

    RecordingCommandList timed;
    g.reset();
    declareFrame(g, test::fakeTexture());
    ASSERT_TRUE(g.execute(device, timed).ok());
    EXPECT_EQ(device.timestampPoolsCreated, 1);
}

}  // namespace
}  // namespace caustics::rg
