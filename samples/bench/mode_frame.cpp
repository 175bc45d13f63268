// `frame` mode: the whole frame as a host engine runs it through CausticsModule (G-buffer, direct
// lighting, caustic maps, forward trace, backward spheres + gather, filter, composite), per-pass GPU
// time medians from the render graph's timestamps, on the built-in scene and builtin:atrium (generated
// stand-ins, labelled as such). Defaults are the paper's section 4: 3 lights, 512x512 maps, 1 ray per
// texel, depth 4, filter off (the paper measured with it off; CAUSTICS_BENCH_FILTER=1 turns it on).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "bench_gpu.h"
#include "bench_modes.h"
#include "caustics/caustics_module.h"
#include "frame_renderer.h"
#include "caustics/scene/builtin_scenes.h"
#include "caustics/scene/gpu_scene.h"

namespace caustics::bench {
namespace {

Status benchFrame(const rhi::DeviceHandle& device, const std::string& name, const BenchOptions& o) {
    CAUSTICS_TRY(scene::Scene sc, scene::makeBuiltin(name));
    CAUSTICS_TRY(scene::GpuScene gpu, scene::GpuScene::create(*device, sc));
    CausticsSettings settings;
    settings.filter = std::getenv("CAUSTICS_BENCH_FILTER") && std::string(std::getenv("CAUSTICS_BENCH_FILTER")) == "1";
    CAUSTICS_TRY(auto module, CausticsModule::create(device, sc, gpu, settings));
    CAUSTICS_TRY(auto renderer, sample::FrameRenderer::create(device, *module, o.width, o.height));
    renderer->graph().setTimingWindow(o.frames);
    const scene::Camera camera = sc.cameras.empty() ? scene::Camera{} : sc.cameras.front();
    for (uint32_t f = 0; f < o.warmupFrames + o.frames; ++f) CAUSTICS_CHECK(renderer->render(camera, f, false));

    std::printf("\nscene    : %s%s, %ux%u, %zu lights, filter %s\n", sc.name.c_str(),
                sc.isStandIn ? " [generated stand-in]" : "", o.width, o.height, sc.lights.size(),
                settings.filter ? "on" : "off");
    std::printf("%-24s %12s\n", "pass", "median ms");
    double total = 0.0;
    for (const auto& pass : renderer->graph().desc().passes) {
        auto ms = renderer->graph().passTimeMs(pass.name);
        if (!ms) continue;
        total += *ms;
        std::printf("%-24s %12.3f\n", pass.name.c_str(), *ms);
    }
    std::printf("%-24s %12.3f\n", "total (sum of passes)", total);
    return okStatus();
}

}  // namespace

int runFrameMode(const BenchOptions& options) {
    auto device = createBenchDevice(options);
    if (!device) {
        std::fprintf(stderr, "caustics-bench frame: %s\n", device.message().c_str());
        return 1;
    }
    std::printf("caustics-bench frame on %s (%s), median of %u frames after %u warm-up\n",
                device.value()->capabilities().adapterName.c_str(), device.value()->capabilities().driverName.c_str(),
                options.frames, options.warmupFrames);
    const char* scenes = std::getenv("CAUSTICS_BENCH_SCENES");
    std::stringstream list(scenes && *scenes ? scenes : "builtin,builtin:atrium");
    std::string name;
    while (std::getline(list, name, ',')) {
        if (Status st = benchFrame(device.value(), name, options); !st) {
            std::fprintf(stderr, "caustics-bench frame: %s: %s\n", name.c_str(), st.message().c_str());
            return 1;
        }
    }
    return 0;
}

}  // namespace caustics::bench
