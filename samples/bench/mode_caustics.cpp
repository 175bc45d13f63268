// `caustics` mode: per-pass GPU time medians of the caustic passes (caustic_passes.h) on the built-in
// scene and builtin:atrium (generated stand-ins, labelled as such), at the paper's section-4 defaults:
// 3 lights, 512x512 maps, 1 ray per texel, depth 4, --width x --height (default 1920x1080).
// Overrides (environment): CAUSTICS_BENCH_SCENES (comma list), CAUSTICS_BENCH_MAP, CAUSTICS_BENCH_RAYS,
// CAUSTICS_BENCH_DEPTH, CAUSTICS_BENCH_FILTER (0/1).
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <sstream>

#include "bench_gpu.h"
#include "bench_modes.h"
#include "caustics/caustic_passes.h"
#include "caustics/frame_context.h"
#include "gbuffer/gbuffer_pass.h"
#include "caustics/scene/builtin_scenes.h"

namespace caustics::bench {
namespace {

using namespace caustics::rhi;

std::string envOr(const char* name, const char* fallback) {
    const char* v = std::getenv(name);
    return v && *v ? v : fallback;
}

int fail(const std::string& what) {
    std::fprintf(stderr, "caustics-bench caustics: %s\n", what.c_str());
    return 1;
}

Status benchScene(IDevice& dev, const std::string& name, const BenchOptions& o, const CausticsSettings& settings) {
    CAUSTICS_TRY(scene::Scene sc, scene::makeBuiltin(name));
    CAUSTICS_TRY(scene::GpuScene gpu, scene::GpuScene::create(dev, sc));
    CAUSTICS_TRY(SceneBindings bindings, SceneBindings::create(dev, gpu, sc));
    BindingLayoutDesc cl;
    cl.setVisibility(ShaderStage::All).add(0, BindingType::ConstantBuffer);
    CAUSTICS_TRY(BindingLayoutHandle cameraLayout, dev.createBindingLayout(cl));
    CAUSTICS_TRY(BufferHandle cameraBuffer, dev.createBuffer(BufferDesc().setByteSize(sizeof(CameraConstants))
                                                                 .setUsage(BufferUsage::Constant).setMemory(MemoryType::Upload)));
    CAUSTICS_TRY(BindingSetHandle cameraSet,
                 dev.createBindingSet(BindingSetDesc().add(BindingSetItem::constantBuffer(0, cameraBuffer)), cameraLayout));
    CAUSTICS_TRY(GBufferPass gbufferPass, GBufferPass::create(dev, bindings.layout, cameraLayout));
    CAUSTICS_TRY(CausticResources resources, CausticResources::create(dev));
    CAUSTICS_TRY(BufferHandle statsReadback, dev.createBuffer(BufferDesc().setByteSize(kStatCount * 4)
                                                                  .setUsage(BufferUsage::CopyDest).setMemory(MemoryType::Readback)));
    rg::RenderGraph graph;
    graph.setTimingWindow(o.frames);
    const scene::Camera camera = sc.cameras.empty() ? scene::Camera{} : sc.cameras[0];
    std::vector<std::string> passNames;
    uint64_t raysLastFrame = 0;
    CausticMapPlan plan;
    for (uint32_t frame = 0; frame < o.warmupFrames + o.frames; ++frame) {
        graph.reset();
        FrameContext fc;
        fc.device = &dev;
        fc.scene = &sc;
        fc.gpuScene = &gpu;
        fc.sceneBindings = &bindings;
        fc.settings = &settings;
        fc.camera = makeCameraConstants(camera, o.width, o.height, frame);
        std::memcpy(cameraBuffer->mappedData(), &fc.camera, sizeof(CameraConstants));
        fc.cameraBuffer = cameraBuffer;
        fc.cameraLayout = cameraLayout;
        fc.cameraSet = cameraSet;
        fc.width = o.width;
        fc.height = o.height;
        fc.frameIndex = frame;
        GBuffer g = gbufferPass.addToGraph(graph, fc);
        CausticFrameInputs in;
        in.device = &dev;
        in.scene = &sc;
        in.gpuScene = &gpu;
        in.sceneBindings = &bindings;
        in.gbuffer = g;
        in.camera = fc.camera;
        in.settings = settings;
        in.frameIndex = frame;
        CAUSTICS_TRY(CausticOutputs out, addCausticPasses(graph, resources, in));
        plan = out.plan;
        graph.markOutput(out.radiance);
        rg::RgBuffer stats = out.stats;
        graph.addPass("bench.readStats", [&](rg::PassBuilder& b) {
            stats = b.read(stats, rg::Access::CopySource);
            b.setSideEffects();
            return [=](rg::PassContext& ctx) { ctx.cmd().copyBuffer(statsReadback, 0, ctx.buffer(stats), 0, kStatCount * 4); };
        });
        CAUSTICS_TRY(CommandListHandle cmd, dev.createCommandList());
        cmd->begin();
        CAUSTICS_CHECK(graph.execute(dev, *cmd));
        cmd->end();
        CAUSTICS_TRY(uint64_t fence, dev.submit(cmd));
        CAUSTICS_CHECK(dev.waitForFence(fence));
        graph.collectTimings(dev);
        uint32_t s[kStatCount];
        CAUSTICS_CHECK(dev.readBuffer(statsReadback, s, sizeof(s)));
        raysLastFrame = 0;
        for (uint32_t l = 0; l < kMaxCausticLights; ++l) raysLastFrame += s[kStatRaysPerLight + l];
    }
    std::printf("scene %s%s: %zu lights, %zu maps (%zu skipped), %ux%u, map %u, %.2f rays/texel, depth %u, filter %s\n",
                name.c_str(), sc.isStandIn ? " (generated stand-in)" : "", sc.lights.size(), plan.maps.size(),
                plan.skippedLights.size(), o.width, o.height, settings.mapResolution, settings.raysPerTexel,
                settings.maxSpecularDepth, settings.filter ? "on" : "off");
    double total = 0.0;
    for (const char* pass : {"gbuffer", "caustics.setup", "caustics.maps", "caustics.forward", "caustics.backward",
                             "caustics.spheres", "caustics.gather", "caustics.resolve", "caustics.temporal",
                             "caustics.atrous.0", "caustics.atrous.1", "caustics.atrous.2", "caustics.history"}) {
        auto ms = graph.passTimeMs(pass);
        if (!ms) continue;
        if (std::strncmp(pass, "caustics.", 9) == 0) total += *ms;
        std::printf("  %-20s %8.3f ms (median of %u frames)\n", pass, *ms, o.frames);
    }
    std::printf("  %-20s %8.3f ms\n", "caustics total", total);
    if (auto fwd = graph.passTimeMs("caustics.forward"); fwd && *fwd > 0.0)
        std::printf("  forward photon paths: %llu per frame, %.1f M paths/s (each path = 1..depth+2 rays)\n",
                    (unsigned long long)raysLastFrame, double(raysLastFrame) / (*fwd * 1e-3) / 1e6);
    return okStatus();
}

}  // namespace

int runCausticsMode(const BenchOptions& options) {
    auto device = createBenchDevice(options);
    if (!device) return fail(device.message());
    CausticsSettings s;
    s.mapResolution = uint32_t(std::atoi(envOr("CAUSTICS_BENCH_MAP", "512").c_str()));
    s.raysPerTexel = float(std::atof(envOr("CAUSTICS_BENCH_RAYS", "1").c_str()));
    s.maxSpecularDepth = uint32_t(std::atoi(envOr("CAUSTICS_BENCH_DEPTH", "4").c_str()));
    s.filter = envOr("CAUSTICS_BENCH_FILTER", "0") == "1";   // the paper measured with the filter off
    if (auto ok = s.validate(); !ok) return fail(ok.message());
    std::printf("caustics-bench caustics on %s\n", device.value()->capabilities().adapterName.c_str());
    std::stringstream scenes(envOr("CAUSTICS_BENCH_SCENES", "builtin,builtin:atrium"));
    for (std::string name; std::getline(scenes, name, ',');) {
        if (auto st = benchScene(*device.value(), name, options, s); !st) return fail(name + ": " + st.message());
    }
    return 0;
}

}  // namespace caustics::bench
