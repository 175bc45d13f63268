// CausticsModule::memoryReport() (caustics/memory_report.h, docs/embedding.md "Memory") against what the
// module really allocated: each entry follows the frame that ran (the filter history at the view's size,
// the sphere TLAS over W x H instance slots), the scene's acceleration structures have their driver
// sizes, and a second view reports only its own resources.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>

#include "caustics/caustics_module.h"
#include "caustics/scene/builtin_scenes.h"
#include "caustics/scene/gpu_scene.h"
#include "caustics/sphere_capacity.h"
#include "builtin_scene_gpu_test.h"

namespace caustics::test {
namespace {

class MemoryReport : public BuiltinSceneGpuTest {
protected:
    void SetUp() override {
        BuiltinSceneGpuTest::SetUp();
        if (HasFatalFailure()) return;
        CausticsSettings s;
        s.mapResolution = 32;
        s.filter = true;   // the history textures exist only with the filter on
        auto m = CausticsModule::create(device, scene, *gpuScene, s);
        ASSERT_TRUE(m) << m.message();
        module = std::move(*m);
    }
    // One executed frame at width x height through `view` (null: the default view).
    void renderFrame(uint32_t width, uint32_t height, CausticsView* view = nullptr) {
        rg::RenderGraph graph;
        FrameInputs in;
        in.camera = cameraViewMatrices(scene.cameras.empty() ? scene::Camera{} : scene.cameras.front(), width, height);
        in.width = width;
        in.height = height;
        in.view = view;
        auto out = module->addPasses(graph, in);
        ASSERT_TRUE(out) << out.message();
        graph.markOutput(out->hdr, rhi::ResourceState::CopySource);
        auto cmd = device->createCommandList();
        ASSERT_TRUE(cmd) << cmd.message();
        (*cmd)->begin();
        ASSERT_TRUE(graph.execute(*device, **cmd));
        (*cmd)->end();
        auto fence = device->submit(*cmd);
        ASSERT_TRUE(fence) << fence.message();
        ASSERT_TRUE(device->waitForFence(*fence));
    }
    static std::map<std::string, uint64_t> byName(const std::vector<MemoryEntry>& entries) {
        std::map<std::string, uint64_t> m;
        for (const MemoryEntry& e : entries) {
            EXPECT_EQ(e.kind, MemoryKind::Persistent) << e.name;
            EXPECT_TRUE(m.emplace(e.name, e.bytes).second) << "duplicate entry " << e.name;
        }
        return m;
    }

    std::unique_ptr<CausticsModule> module;
};

TEST_F(MemoryReport, EntriesFollowTheFrameThatRan) {
    renderFrame(64, 48);
    auto small = byName(module->memoryReport());
    renderFrame(128, 96);
    const std::vector<MemoryEntry> report = module->memoryReport();
    auto large = byName(report);

    // The default view's filter history, two copies of each (ping-pong), kept per listed 8x8 tile in a
    // pool (docs/caustics.md "Filter", "Memory"): RGBA16F colour and RG32UI guides, 8 bytes per texel of
    // the pool, whose capacity is all the screen's tiles in whole rows of 128 tiles for views this small
    // (at most 1024 tiles: a quarter of the screen above that); R32UI tile state and slot map per tile.
    const uint64_t poolTexels = 256u * 64u;   // 128x96: 192 tiles -> 2 rows
    for (const char* copy : {"0", "1"}) {
        const std::string h = std::string("view.history.");
        EXPECT_EQ(large[h + "color" + copy], poolTexels * 8);
        EXPECT_EQ(large[h + "guides" + copy], poolTexels * 8);
        EXPECT_EQ(large[h + "tiles" + copy], (128u / 8) * (96u / 8) * 4u);
        EXPECT_EQ(large[h + "slots" + copy], (128u / 8) * (96u / 8) * 4u);
    }
    EXPECT_EQ(small["view.history.color0"], 128u * 64u * 8u);   // 64x48: 48 tiles -> 1 row

    // Acceleration structures report the driver's sizes: the scene's (built at GpuScene::create) and the
    // spheres' (docs/caustics.md "Memory"): a BLAS of one AABB per sphere slot and a TLAS of that one
    // BLAS. Below the 2^15-slot floor the slots are the slot limit, 2 x W x H (a pixel's sphere and its
    // lobe branch's, caustics/sphere_capacity.h): 4x the pixels, 4x the AABBs (24 bytes each, exact) and about 4x the BLAS (lavapipe: the [ measured ] line; bound 3.5 .. 4.5, a BLAS that did
    // not follow the image would give 1); the one-instance TLAS is the same at both sizes.
    EXPECT_GT(large["scene.tlas"], 0u);
    EXPECT_GT(large["scene.slot0.tlas"], 0u);
    EXPECT_GT(large["caustics.sphere_tlas"], 0u);
    EXPECT_EQ(large["caustics.sphere_tlas"], small["caustics.sphere_tlas"]);
    EXPECT_EQ(large["caustics.sphere_aabbs"], kMaxSpheresPerPixel * 128u * 96u * 24u);
    EXPECT_EQ(small["caustics.sphere_aabbs"], kMaxSpheresPerPixel * 64u * 48u * 24u);
    uint64_t blases = 0;
    for (const auto& [name, bytes] : large)
        if (name.rfind("scene.blases (", 0) == 0) blases = bytes;
    EXPECT_GT(blases, 0u) << "no scene.blases entry";
    const double ratio = double(large["caustics.sphere_blas"]) / double(small["caustics.sphere_blas"]);
    std::printf("[ measured ] sphere BLAS %llu bytes at 64x48, %llu at 128x96 (ratio %.3f); total %llu bytes\n",
                (unsigned long long)small["caustics.sphere_blas"], (unsigned long long)large["caustics.sphere_blas"],
                ratio, (unsigned long long)totalBytes(report));
    EXPECT_GT(ratio, 3.5);
    EXPECT_LT(ratio, 4.5);

    uint64_t sum = 0;
    for (const MemoryEntry& e : report) sum += e.bytes;
    EXPECT_EQ(totalBytes(report), sum);
}

TEST_F(MemoryReport, ASecondViewReportsItsOwnHistory) {
    auto view = module->createView();
    ASSERT_TRUE(view) << view.message();
    auto before = byName(module->memoryReport(**view));
    EXPECT_EQ(before.count("view.history.color0"), 0u) << "history before the view rendered anything";
    renderFrame(96, 64, view->get());
    auto after = byName(module->memoryReport(**view));
    EXPECT_EQ(after["view.history.color0"], 128u * 64u * 8u);   // 96 tiles: one pool row of 128
    // The default view rendered nothing: no history in the module's report.
    auto own = byName(module->memoryReport());
    EXPECT_EQ(own.count("view.history.color0"), 0u);
}

}  // namespace
}  // namespace caustics::test
