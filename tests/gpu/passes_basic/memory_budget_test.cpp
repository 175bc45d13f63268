// The module's memory at game resolutions (docs/caustics.md "Memory"), from frame graphs built and
// compiled against lavapipe's memory requirements, never executed (1080p and 4K frames would take
// minutes there): every persistent resource the build sized (memoryReport) plus the transients' aliased
// peak (appendFrameMemory, the "peak in one frame" line), the host's scene excluded.
//
// The team's targets (<= 160 MiB at 1920x1080, <= 320 MiB at 3840x2160, filter and second type on)
// are for what the module adds to its own frame (its G-buffer, direct lighting and composite, which a
// host replaces with its own in causticsOnly mode): the caustic passes and the filter.
#include <gtest/gtest.h>

#include <cstdio>

#include "caustics/caustic_passes.h"
#include "caustics/sphere_capacity.h"
#include "caustics/caustics_module.h"
#include "caustics/render_graph/memory_sizer.h"
#include "builtin_scene_gpu_test.h"

namespace caustics::test {
namespace {

constexpr double kMiB = 1048576.0;

class MemoryBudget : public BuiltinSceneGpuTest {
protected:
    // The module's report for one frame graph at width x height with `s` (a fresh module: allocations
    // start from this size).
    std::vector<MemoryEntry> frameReport(const CausticsSettings& s, uint32_t width, uint32_t height,
                                         uint64_t* heap = nullptr) {
        auto module = CausticsModule::create(device, scene, *gpuScene, s);
        EXPECT_TRUE(module) << module.message();
        if (!module) return {};
        rg::RenderGraph graph;
        FrameInputs in;
        in.camera = cameraViewMatrices(scene.cameras.empty() ? scene::Camera{} : scene.cameras.front(), width, height);
        in.width = width;
        in.height = height;
        auto out = (*module)->addPasses(graph, in);
        EXPECT_TRUE(out) << out.message();
        if (!out) return {};
        graph.markOutput(out->display, rhi::ResourceState::CopySource);
        graph.markOutput(out->hdr, rhi::ResourceState::CopySource);
        EXPECT_TRUE(graph.compile(rg::DeviceMemorySizer(*device)));
        if (heap) *heap = graph.plan() ? graph.plan()->heapSize : 0;
        std::vector<MemoryEntry> report = (*module)->memoryReport();
        appendFrameMemory(graph, report);
        return report;
    }
    static uint64_t entry(const std::vector<MemoryEntry>& report, const std::string& name) {
        for (const MemoryEntry& e : report)
            if (e.name == name) return e.bytes;
        return 0;
    }
    static CausticsSettings gameSettings(bool filter, bool caustics, bool apart = CausticsSettings{}.filterSecondTypeApart) {
        CausticsSettings s;   // paper defaults: 512^2 maps, 1 ray per texel, 2^20 stored hits
        s.secondType = true;
        s.filter = filter;
        s.causticsEnabled = caustics;
        s.filterSecondTypeApart = apart;
        return s;
    }
    // Module memory (persistent + peak, host scene excluded) with the filter on, off, and caustics off.
    struct Shares {
        double filterOn, filterOff, frame;
        double caustics() const { return filterOff - frame; }
        double filter() const { return filterOn - filterOff; }
    };
    Shares shares(uint32_t width, uint32_t height, bool apart = CausticsSettings{}.filterSecondTypeApart) {
        Shares s{};
        s.filterOn = double(moduleFrameBytes(frameReport(gameSettings(true, true, apart), width, height)));
        s.filterOff = double(moduleFrameBytes(frameReport(gameSettings(false, true, apart), width, height)));
        s.frame = double(moduleFrameBytes(frameReport(gameSettings(false, false, apart), width, height)));
        std::printf("[ measured ] %ux%u%s: module %.1f MiB with the filter (%.1f without; filter share %.1f); "
                    "caustic passes %.1f MiB; the module's own frame without caustics %.1f MiB\n",
                    width, height, apart ? " (second type apart)" : "", s.filterOn / kMiB, s.filterOff / kMiB, s.filter() / kMiB, s.caustics() / kMiB,
                    s.frame / kMiB);
        return s;
    }
};

// Measured 2026-12-04 (lavapipe, builtin scene; the [ measured ] lines): the caustic passes plus the
// filter add 85.0 MiB at 1080p (68.5 + 16.5) and 276.1 MiB at 4K (210.6 + 65.5) to the module's own frame
// at the default settings; with the second type filtered apart (in list order, docs/caustics.md
// "Second-type memory") 96.0 MiB (68.5 + 27.5) and 319.6 MiB (210.6 + 109.0): its run adds its history
// pool (43.5 MiB at 4K), the frame's peak is the merged one's. Sizes are deterministic (no frame runs, no
// noise), so the bounds are the targets themselves, for both.
TEST_F(MemoryBudget, CausticPassesAndFilterFitTheTargetsAt1080pAnd4K) {
    for (bool apart : {false, true}) {
        SCOPED_TRACE(apart ? "second type filtered apart" : "merged");
        const Shares hd = shares(1920, 1080, apart);
        EXPECT_LE(hd.caustics() + hd.filter(), 160.0 * kMiB);
        EXPECT_LE(hd.filter(), 64.0 * kMiB) << "the filter's extra memory (issue 20's target)";
        const Shares uhd = shares(3840, 2160, apart);
        EXPECT_LE(uhd.caustics() + uhd.filter(), 320.0 * kMiB);
    }
}

// The second type filtered apart keeps its buffer, image and guides in list order: one texel per listed
// specular pixel (a tenth of the builtin view's pixels), never a screen's worth; no first-type texture
// exists unless an AOV asks for it. With an AOV of one type (the types' own screen textures) it keeps
// the screen layout.
TEST_F(MemoryBudget, SecondTypeFilteredApartFollowsTheSpecularPixels) {
    constexpr uint32_t w = 3840, h = 2160;
    const std::vector<MemoryEntry> apart = frameReport(gameSettings(true, true, true), w, h);
    CausticsSettings aov = gameSettings(true, true, true);
    aov.aov = CausticsAov::SecondType;
    const std::vector<MemoryEntry> screen = frameReport(aov, w, h);
    EXPECT_EQ(entry(apart, "caustics.firstType"), 0u);
    EXPECT_GE(entry(screen, "caustics.secondType"), uint64_t(w) * h * 16) << "a screen image (a device may pad it)";
    // The builtin view's glass covers about a tenth of the pixels: each list-ordered image takes a small
    // part of its screen-sized twin (measured 8x smaller, lavapipe and H200 alike, padding included).
    for (const char* name : {"caustics.secondType", "caustics.secondTypeDepthMotion", "caustics.secondTypeNormal",
                             "caustics.secondTypeObjectId", "caustics.secondTypeBuffer"}) {
        EXPECT_GT(entry(apart, name), 0u) << name;
        EXPECT_LT(entry(apart, name), entry(screen, name) / 4) << name << ": sized by the list, not the screen";
    }
    EXPECT_LT(entry(apart, "caustics.specularIndex"), uint64_t(w) * h) << "one 16-byte texel per 8x8 tile";
}

// The "peak in one frame" line is the graph's aliased heap, less than its transients added up.
TEST_F(MemoryBudget, PeakLineIsTheGraphsAliasedHeap) {
    uint64_t heap = 0;
    const std::vector<MemoryEntry> report = frameReport(gameSettings(true, true), 320, 240, &heap);
    uint64_t transients = 0, peaks = 0;
    for (const MemoryEntry& e : report) {
        if (e.kind == MemoryKind::Transient) transients += e.bytes;
        if (e.kind == MemoryKind::FramePeak) ++peaks;
    }
    EXPECT_EQ(peaks, 1u);
    EXPECT_GT(heap, 0u);
    EXPECT_EQ(entry(report, "frame.peak_transients"), heap);
    EXPECT_LT(heap, transients) << "the graph aliases: its heap holds less than every transient at once";
    uint64_t persistent = 0;
    for (const MemoryEntry& e : report)
        if (e.kind == MemoryKind::Persistent && !isHostSceneMemory(e)) persistent += e.bytes;
    EXPECT_EQ(moduleFrameBytes(report), persistent + heap);
}

// Memory that follows the work: hits only for the second type, one accumulation buffer and one
// resolved image unless an AOV shows a type alone, sphere structures for the specular surfaces in view.
TEST_F(MemoryBudget, BuffersFollowWhatTheFrameNeeds) {
    const uint32_t w = 1920, h = 1080;
    CausticsSettings s = gameSettings(false, true);
    const std::vector<MemoryEntry> both = frameReport(s, w, h);
    // At most one hit per forward launch: the builtin scene's launch bound (2^19) is under maxStoredHits.
    EXPECT_LT(entry(both, "caustics.hits"), uint64_t(s.maxStoredHits) * sizeof(CausticHit));
    EXPECT_GE(entry(both, "caustics.hits"), uint64_t(s.mapResolution) * s.mapResolution * sizeof(CausticHit));
    EXPECT_GT(entry(both, "caustics.firstTypeBuffer"), 0u);
    EXPECT_EQ(entry(both, "caustics.secondTypeBuffer"), 0u) << "one buffer accumulates both types";
    EXPECT_EQ(entry(both, "caustics.secondType"), 0u);
    // Sphere slots follow the specular surfaces in view (caustics/sphere_capacity.h): the builtin view's
    // glass covers about a tenth of the image, so more than the floor and well under a slot per pixel.
    EXPECT_GT(entry(both, "caustics.spheres"), uint64_t(kMinSphereAllocation) * sizeof(CausticSphere));
    EXPECT_LT(entry(both, "caustics.spheres"), uint64_t(w * h / 4) * sizeof(CausticSphere));

    s.secondType = false;
    const std::vector<MemoryEntry> first = frameReport(s, w, h);
    EXPECT_LT(entry(first, "caustics.hits"), 4096u) << "no second type, no stored hits (one placeholder record)";
    EXPECT_EQ(entry(first, "caustics.spheres"), 0u);

    s.secondType = true;
    s.aov = CausticsAov::SecondType;
    const std::vector<MemoryEntry> aov = frameReport(s, w, h);
    EXPECT_EQ(entry(aov, "caustics.secondTypeBuffer"), entry(aov, "caustics.firstTypeBuffer"));
    EXPECT_GT(entry(aov, "caustics.secondType"), 0u);
}

}  // namespace
}  // namespace caustics::test
