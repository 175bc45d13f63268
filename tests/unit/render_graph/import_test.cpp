// Imports: one physical object imported twice in one graph (two views sharing a persistent object) is
// one resource, so its uses are ordered and barriered as one.
#include <gtest/gtest.h>

#include "fake_rhi_objects.h"
#include "caustics/render_graph/render_graph.h"

namespace caustics::rg {
namespace {

TEST(RenderGraphImport, SameBufferImportedTwiceIsOneResourceAtItsLatestVersion) {
    RenderGraph g;
    rhi::BufferHandle shared = test::fakeBuffer();
    RgBuffer first = g.importBuffer("first view", shared, rhi::ResourceState::ShaderResource, rhi::ResourceState::ShaderResource);
    RgBuffer written;
    g.addPass("first view writes", [&](PassBuilder& b) {
        written = b.write(first, Access::StorageWrite);
        return [](PassContext&) {};
    });
    RgBuffer second = g.importBuffer("second view", shared, rhi::ResourceState::ShaderResource, rhi::ResourceState::CopySource);
    EXPECT_EQ(second.index, first.index);
    EXPECT_EQ(second.version, written.version) << "the second import continues after the first view's write";
    EXPECT_EQ(g.desc().resources[first.index].finalState, rhi::ResourceState::CopySource);
    RgBuffer other = g.importBuffer("another object", test::fakeBuffer(), rhi::ResourceState::ShaderResource,
                                    rhi::ResourceState::ShaderResource);
    EXPECT_NE(other.index, first.index);
}

}  // namespace
}  // namespace caustics::rg
