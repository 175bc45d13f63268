// The sample refuses frames that do not fit the device from a measurement of the module's render graph
// (samples/sponza/frame_budget.h): the transient heap at two small sizes, fitted as fixed + per pixel.
// These tests hold the fit against the graph itself at other sizes and settings.
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
    std::unique_ptr<CausticsModule> makeModule(uint32_t maxStoredHits) {
        CausticsSettings s;
        s.mapResolution = 64;
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

// Measured (lavapipe, the "[ measured ]" lines): the fit from 64x48 and 128x96 predicts the heap at
// 200x150 0.30 % low and at 320x240 exactly (the aliased heap is per-pixel images plus fixed buffers,
// each rounded to its alignment). Bound: 2 %, about 6x the measurement; a model without the per-pixel
// part is 73 % low at 320x240.
TEST_F(FrameMemory, FitFromTwoSmallSizesPredictsTheHeapAtLargerOnes) {
    auto module = makeModule(1u << 16);
    ASSERT_TRUE(module);
    auto memory = sample::measureFrameMemory(*device, *module);
    ASSERT_TRUE(memory) << memory.message();
    EXPECT_GT(memory->heapBytesPerPixel, 100.0);   // G-buffer, direct, caustic and filter images
    for (auto [w, h] : {std::pair{200u, 150u}, std::pair{320u, 240u}}) {
        double actual = double(graphHeap(*module, w, h));
        double predicted = double(memory->heapBytes(w, h));
        std::printf("[ measured ] %ux%u: heap %.0f bytes, predicted %.0f (%.3f %%)\n", w, h, actual, predicted,
                    100.0 * (predicted - actual) / actual);
        EXPECT_NEAR(predicted, actual, 0.02 * actual) << w << "x" << h;
    }
}

// The hit buffer (CausticsSettings::maxStoredHits x sizeof(CausticHit)) does not depend on the image:
// it lands in the fixed part, and is named as its largest piece. Measured: the fixed part grows by
// exactly the hit buffer's growth (78643200 bytes); bound 1 %.
TEST_F(FrameMemory, HitBufferIsTheFixedPartsLargestPiece) {
    auto small = makeModule(1u << 16), large = makeModule(1u << 20);
    ASSERT_TRUE(small && large);
    auto a = sample::measureFrameMemory(*device, *small);
    auto b = sample::measureFrameMemory(*device, *large);
    ASSERT_TRUE(a && b);
    double growth = double(b->fixedBytes) - double(a->fixedBytes);
    double hits = double((1u << 20) - (1u << 16)) * sizeof(CausticHit);
    std::printf("[ measured ] fixed part %llu -> %llu bytes (hit buffer growth %.0f)\n",
                static_cast<unsigned long long>(a->fixedBytes), static_cast<unsigned long long>(b->fixedBytes), hits);
    EXPECT_NEAR(growth, hits, 0.01 * hits);
    EXPECT_EQ(b->largestFixed, "caustics.hits");
    EXPECT_EQ(b->largestFixedBytes, uint64_t(1u << 20) * sizeof(CausticHit));
    EXPECT_NEAR(b->heapBytesPerPixel, a->heapBytesPerPixel, 1e-6 * a->heapBytesPerPixel);
}

}  // namespace
}  // namespace caustics::test
