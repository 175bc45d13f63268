// What the graph tells a host instead of failing silently (docs/embedding.md "The module on the host"):
// a library output nobody consumes, an error a pass only logged, the device's placement granularity.
#include <gtest/gtest.h>

#include "fake_memory_sizer.h"
#include "recording_device.h"
#include "caustics/render_graph/render_graph.h"
#include "caustics/rhi/log.h"
#include "caustics/rhi/log_capture.h"

namespace caustics::rg {
namespace {
using rhi::ResourceState;
using test::FakeMemorySizer;
using test::texDesc;

// "library.make" writes a texture the library hands to the host, expecting it to be consumed.
RgTexture libraryOutput(RenderGraph& g) {
    RgTexture out;
    g.addPass("library.make", [&](PassBuilder& b) {
        out = b.write(b.createTexture("library.image", texDesc()), Access::StorageWrite);
        return [](PassContext& ctx) { ctx.cmd().dispatch(1); };
    });
    g.expectConsumer({out}, "the library");
    return out;
}

TEST(RenderGraphContract, LibraryOutputNothingConsumesIsACompileError) {
    RenderGraph g;
    libraryOutput(g);
    Status s = g.compile(FakeMemorySizer());
    ASSERT_FALSE(s.ok()) << "every pass of the library would be culled without a word";
    EXPECT_NE(s.message().find("'library.image'"), std::string::npos) << s.message();
    EXPECT_NE(s.message().find("the library"), std::string::npos) << s.message();
    EXPECT_NE(s.message().find("markOutput"), std::string::npos) << s.message();
}

// A library hands back several images (display, hdr, caustics): reading any one of them keeps its work.
TEST(RenderGraphContract, OneOfSeveralLibraryOutputsConsumedIsEnough) {
    RenderGraph g;
    RgTexture a, b;
    g.addPass("library.a", [&](PassBuilder& pb) {
        a = pb.write(pb.createTexture("library.a", texDesc()), Access::StorageWrite);
        return [](PassContext&) {};
    });
    g.addPass("library.b", [&](PassBuilder& pb) {
        pb.read(a, Access::SampledRead);
        b = pb.write(pb.createTexture("library.b", texDesc()), Access::StorageWrite);
        return [](PassContext&) {};
    });
    g.expectConsumer({a, b}, "the library");
    Status none = g.compile(FakeMemorySizer());
    ASSERT_FALSE(none.ok());
    EXPECT_NE(none.message().find("'library.a', 'library.b'"), std::string::npos) << none.message();
    g.markOutput(a);
    EXPECT_TRUE(g.compile(FakeMemorySizer()).ok()) << "the host reads a; b is culled, as it should";
}

TEST(RenderGraphContract, LibraryOutputMarkedByTheHostCompiles) {
    RenderGraph g;
    g.markOutput(libraryOutput(g));
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    EXPECT_TRUE(g.plan()->passKept[0]);
}

TEST(RenderGraphContract, LibraryOutputReadByAHostPassThatIsKeptCompiles) {
    RenderGraph g;
    RgTexture image = libraryOutput(g);
    RgTexture copy;
    g.addPass("host.copy", [&](PassBuilder& b) {
        b.read(image, Access::CopySource);
        copy = b.write(b.createTexture("host.image", texDesc()), Access::CopyDest);
        return [](PassContext&) {};
    });
    g.markOutput(copy);
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    EXPECT_TRUE(g.plan()->passKept[0]);
}

// The host's copy pass exists but its result is not marked: it is culled, so the library's output is
// consumed by no kept pass and the error still comes (the trap of docs/embedding.md, a black image).
TEST(RenderGraphContract, LibraryOutputReadOnlyByACulledPassIsAnError) {
    RenderGraph g;
    RgTexture image = libraryOutput(g);
    g.addPass("host.copy", [&](PassBuilder& b) {
        b.read(image, Access::CopySource);
        b.write(b.createTexture("host.image", texDesc()), Access::CopyDest);
        return [](PassContext&) {};
    });
    EXPECT_FALSE(g.compile(FakeMemorySizer()).ok());
}

TEST(RenderGraphContract, ErrorAPassOnlyLogsFailsExecute) {
    setLogCallback([](LogLevel, std::string_view) {});   // keep the expected error off the test output
    test::RecordingDevice device;
    test::RecordingCommandList cmd;
    RenderGraph g;
    g.addPass("skips.its.work", [&](PassBuilder& b) {
        b.setSideEffects();
        return [](PassContext&) { log(LogLevel::Error, "binding set: texture 'x' has no Storage usage"); };
    });
    g.addPass("after", [&](PassBuilder& b) {
        b.setSideEffects();
        return [](PassContext&) { log(LogLevel::Error, "a second error"); };
    });
    Status s = g.execute(device, cmd);
    setLogCallback(nullptr);
    ASSERT_FALSE(s.ok()) << "the pass skipped its dispatch: execute() must not report ok";
    EXPECT_NE(s.message().find("'skips.its.work'"), std::string::npos) << s.message();
    EXPECT_NE(s.message().find("no Storage usage"), std::string::npos) << s.message();
    EXPECT_EQ(s.message().find("second"), std::string::npos) << "the FIRST error: " << s.message();
}

TEST(RenderGraphContract, WarningsDoNotFailExecute) {
    test::RecordingDevice device;
    test::RecordingCommandList cmd;
    RenderGraph g;
    g.addPass("warns", [&](PassBuilder& b) {
        b.setSideEffects();
        return [](PassContext&) { log(LogLevel::Debug, "only a note"); };
    });
    EXPECT_TRUE(g.execute(device, cmd).ok());
}

// The page a buffer and an image must not share is the device's (bufferImageGranularity): the Vulkan
// backend pads each virtual resource's requirements to it (VulkanMemoryRequirements test); the graph
// adds no page of its own (it used to put every transient on a 1024-byte boundary).
TEST(RenderGraphContract, PlacementFollowsTheDevicesRequirementsAlone) {
    RenderGraph g;
    RgTexture a, c;
    RgBuffer b;
    g.addPass("make", [&](PassBuilder& pb) {
        a = pb.write(pb.createTexture("a", texDesc(3, 3)), Access::StorageWrite);   // 36 bytes
        b = pb.write(pb.createBuffer("b", test::bufDesc(100)), Access::StorageWrite);
        c = pb.write(pb.createTexture("c", texDesc(5, 1)), Access::StorageWrite);   // 20 bytes
        return [](PassContext&) {};
    });
    g.markOutput(a);
    g.markOutput(b);
    g.markOutput(c);
    ASSERT_TRUE(g.compile(FakeMemorySizer(16)).ok());
    for (uint32_t r : {a.index, b.index, c.index}) {
        ASSERT_TRUE(g.plan()->heapOffset[r].has_value());
        EXPECT_EQ(*g.plan()->heapOffset[r] % 16, 0u);
    }
    // 36 -> 48, 100 -> 112, 20: packed on 16-byte boundaries.
    EXPECT_EQ(g.plan()->heapSize, 48u + 112u + 20u);
}

}  // namespace
}  // namespace caustics::rg
