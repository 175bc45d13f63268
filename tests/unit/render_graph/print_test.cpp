// Text and Graphviz output name every pass and every access edge.
#include <gtest/gtest.h>

#include "fake_memory_sizer.h"
#include "fake_rhi_objects.h"
#include "caustics/render_graph/render_graph.h"

namespace caustics::rg {
namespace {
using test::FakeMemorySizer;
using test::texDesc;

void buildSample(RenderGraph& g) {
    RgTexture out = g.importTexture("hostOutput", test::fakeTexture(), rhi::ResourceState::Common,
                                    rhi::ResourceState::ShaderResource);
    RgTexture lit;
    g.addPass("lighting", [&](PassBuilder& b) {
        lit = b.write(b.createTexture("litColor", texDesc()), Access::StorageWrite);
        return [](PassContext&) {};
    });
    g.addPass("debugView", [&](PassBuilder& b) {
        b.read(lit);
        b.write(b.createTexture("debug", texDesc()), Access::RenderTarget);
        return [](PassContext&) {};
    });
    g.addPass("composite", [&](PassBuilder& b) {
        b.read(lit);
        out = b.write(out, Access::StorageWrite);
        return [](PassContext&) {};
    });
    g.markOutput(out);
}

TEST(RenderGraphPrint, TextNamesEveryPassAndMarksCulled) {
    RenderGraph g;
    buildSample(g);
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    std::string text = g.printText();
    for (const PassDecl& p : g.desc().passes) EXPECT_NE(text.find("'" + p.name + "'"), std::string::npos) << p.name;
    EXPECT_NE(text.find("'debugView' [culled]"), std::string::npos) << text;
    EXPECT_NE(text.find("edge 'lighting' -> 'composite' via 'litColor' v1"), std::string::npos) << text;
    EXPECT_NE(text.find("final barrier texture 'hostOutput' UnorderedAccess -> ShaderResource"), std::string::npos)
        << text;
}

TEST(RenderGraphPrint, GraphvizHasEveryPassAndAccessEdge) {
    RenderGraph g;
    buildSample(g);
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    std::string dot = g.printGraphviz();
    EXPECT_EQ(dot.rfind("digraph", 0), 0u);
    const GraphDesc& d = g.desc();
    for (uint32_t p = 0; p < d.passes.size(); ++p) {
        EXPECT_NE(dot.find("p" + std::to_string(p) + " [shape=box, label=\"" + d.passes[p].name), std::string::npos);
        for (const AccessDecl& a : d.passes[p].accesses) {
            std::string pass = "p" + std::to_string(p);
            std::string res = "r" + std::to_string(a.resource) + "v" + std::to_string(a.version);
            std::string edge = a.write ? pass + " -> " + res : res + " -> " + pass;
            EXPECT_NE(dot.find(edge), std::string::npos) << edge << "\n" << dot;
        }
    }
}

TEST(PassTimings, MedianOverWindowIgnoresOldestAndOutliers) {
    // Timings come from the GPU in execute(); here the median store is exercised directly.
    PassTimings t(4);
    for (double ms : {5.0, 1.0, 2.0, 100.0, 3.0}) t.add("p", ms);   // window keeps 1, 2, 100, 3
    ASSERT_TRUE(t.medianMs("p"));
    EXPECT_DOUBLE_EQ(*t.medianMs("p"), 2.5);
    EXPECT_EQ(t.sampleCount("p"), 4u);
    EXPECT_FALSE(t.medianMs("other"));
}

}  // namespace
}  // namespace caustics::rg
