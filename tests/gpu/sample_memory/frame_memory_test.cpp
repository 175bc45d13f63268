// The sample refuses frames that do not fit the device from the module's render graph built and sized at
// the frame's own size (samples/sponza/frame_budget.h), and explains a refusal with a fit of the heap
// from two small sizes (fixed + per pixel). These tests hold both against the graph itself.
#include <gtest/gtest.h>

#include <cstdio>

#include "caustics/caustic_passes.h"
#include "caustics/render_graph/memory_sizer.h"
#include "caustics/scene/builtin_scenes.h"
#include "caustics/scene/gpu_scene.h"
#include "frame_budget.h"
#include "builtin_scene_gpu_test.h"

namespace caustics::test {
namespace {

class FrameMemory : public BuiltinSceneGpuTest {
protected:
    std::unique_ptr<CausticsModule> makeModule(uint32_t maxStoredHits, uint32_t mapResolution = 64) {
        CausticsSettings s;
        s.mapResolution = mapResolution;
        s.maxStoredHits = maxStoredHits;
        auto m = CausticsModule::create(device, scene, *gpuScene, s);
        EXPECT_TRUE(m) << m.message();
        return m ? std::move(*m) : nullptr;
    }
    // The transient heap of the module's frame graph at width x height (built, compiled, not executed).
    uint64_t graphHeap(CausticsModule& module, uint32_t width, uint32_t height) {
        rg::RenderGraph graph;
        FrameInputs in;
        in.camera = cameraViewMatrices(scene::Camera{}, width, height);
        in.width = width;
        in.height = height;
        auto out = module.addPasses(graph, in);
        EXPECT_TRUE(out) << out.message();
        if (!out) return 0;
        graph.markOutput(out->display, rhi::ResourceState::CopySource);
        graph.markOutput(out->hdr, rhi::ResourceState::CopySource);
        EXPECT_TRUE(graph.compile(rg::DeviceMemorySizer(*device)));
        return graph.plan() ? graph.plan()->heapSize : 0;
    }
};

// The check measures the heap at the size it checks, so it is exact on any device: a fit from two small
// sizes is exact on lavapipe but came out 4.5 % / 2.2 % under the graph's heap on the H200 at 96x72 /
// 112x84 (docs/measurements/h200/sample_memory_fit.txt), the unsafe side for a refusal. Here the check
// accepts a frame whose heap and whole frame meet the limits exactly and refuses one byte less, at sizes
// under and past kMinSphereAllocation; the fit's prediction is printed beside (not a decision any more).
TEST_F(FrameMemory, CheckMeasuresTheHeapAtTheCheckedSizeAndHoldsItToTheByte) {
    auto module = makeModule(1u << 16);
    ASSERT_TRUE(module);
    auto fit = sample::measureFrameMemory(*device, *module);
    ASSERT_TRUE(fit) << fit.message();
    EXPECT_GT(fit->heapBytesPerPixel, 100.0);   // G-buffer, direct, caustic and filter images
    for (auto [w, h] : {std::pair{96u, 72u}, std::pair{112u, 84u}, std::pair{320u, 240u}, std::pair{640u, 480u}}) {
        const uint64_t actual = graphHeap(*module, w, h);
        auto measured = sample::frameHeapBytes(*device, *module, w, h);
        ASSERT_TRUE(measured) << measured.message();
        const double predicted = double(fit->fixedBytes) + fit->heapBytesPerPixel * double(w) * double(h);
        std::printf("[ measured ] %ux%u: heap %llu bytes, fit from 64x48 and 128x96 %.0f (%+.3f %%)\n", w, h,
                    static_cast<unsigned long long>(actual), predicted, 100.0 * (predicted - double(actual)) / double(actual));
        EXPECT_EQ(*measured, actual) << w << "x" << h;

        rhi::Capabilities limits = device->capabilities();
        limits.deviceMemoryBytes = 0;
        limits.maxAllocationBytes = actual;
        EXPECT_TRUE(sample::checkFrameFitsDevice(*device, *module, w, h, 0, &limits)) << w << "x" << h;
        limits.maxAllocationBytes = actual - 1;
        Status refused = sample::checkFrameFitsDevice(*device, *module, w, h, 0, &limits);
        EXPECT_FALSE(refused) << w << "x" << h;
        EXPECT_NE(refused.message().find("render-graph transient heap"), std::string::npos) << refused.message();

        limits.maxAllocationBytes = 0;
        limits.deviceMemoryBytes = actual + sample::persistentFrameBytes(*device, w, h, module->settings());
        EXPECT_TRUE(sample::checkFrameFitsDevice(*device, *module, w, h, 0, &limits)) << w << "x" << h;
        limits.deviceMemoryBytes -= 1;
        refused = sample::checkFrameFitsDevice(*device, *module, w, h, 0, &limits);
        EXPECT_FALSE(refused) << w << "x" << h;
        EXPECT_NE(refused.message().find("of device memory"), std::string::npos) << refused.message();
    }
}

// The hit buffer (CausticsSettings::maxStoredHits x sizeof(CausticHit), at most one per forward launch)
// does not depend on the image: it lands in the fixed part, and is named as its largest piece. 1024^2
// maps launch past 2^20 photons, so maxStoredHits sizes it. Measured: the fixed part grows by 58.7 MB
// for the hit buffer's 62.9 MB (the maps alias under the larger buffer).
TEST_F(FrameMemory, HitBufferIsTheFixedPartsLargestPiece) {
    auto small = makeModule(1u << 16, 1024), large = makeModule(1u << 20, 1024);
    ASSERT_TRUE(small && large);
    auto a = sample::measureFrameMemory(*device, *small);
    auto b = sample::measureFrameMemory(*device, *large);
    ASSERT_TRUE(a && b);
    double growth = double(b->fixedBytes) - double(a->fixedBytes);
    double hits = double((1u << 20) - (1u << 16)) * sizeof(CausticHit);
    std::printf("[ measured ] fixed part %llu -> %llu bytes (hit buffer growth %.0f)\n",
                static_cast<unsigned long long>(a->fixedBytes), static_cast<unsigned long long>(b->fixedBytes), hits);
    // The larger hit buffer holds the heap at every pass it lives through; the other fixed buffers
    // (1024^2 maps and emitters) alias under it, so the growth is the hits' less at most those.
    const double smallHits = double(1u << 16) * sizeof(CausticHit);
    EXPECT_LE(growth, 1.01 * hits);
    EXPECT_GE(growth, hits - (double(a->fixedBytes) - smallHits));
    EXPECT_GE(double(b->fixedBytes), double(1u << 20) * sizeof(CausticHit));
    EXPECT_EQ(b->largestFixed, "caustics.hits");
    EXPECT_EQ(b->largestFixedBytes, uint64_t(1u << 20) * sizeof(CausticHit));
    EXPECT_NEAR(b->heapBytesPerPixel, a->heapBytesPerPixel, 1e-6 * a->heapBytesPerPixel);
}

}  // namespace
}  // namespace caustics::test
