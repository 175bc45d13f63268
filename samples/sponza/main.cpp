// caustics-sponza: renders a scene with the caustics module, headless by default (writes --out), or
// in a window (--window). Prints the scene name (stand-ins labelled as such) and per-pass GPU times.
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <string>
#include <vector>

#include "camera_setup.h"
#include "animation_render.h"
#include "caustics/caustics_module.h"
#include "cli_options.h"
#include "settings_fields.h"
#include "frame_budget.h"
#include "finite_output.h"
#include "frame_renderer.h"
#include "image_file.h"
#include "caustics/reference/reference_tracer.h"
#include "caustics/rhi/rhi.h"
#include "caustics/scene/gpu_scene.h"
#include "output_paths.h"
#include "scene_checks.h"
#include "scene_source.h"
#include "still_render.h"
#include "viewer_app.h"

using namespace caustics;

namespace {

std::atomic<uint32_t> gValidationProblems{0};

CausticsAov toCausticsAov(sample::Aov aov) {
    switch (aov) {
        case sample::Aov::Final: return CausticsAov::Final;
        case sample::Aov::Albedo: return CausticsAov::Albedo;
        case sample::Aov::Normal: return CausticsAov::Normal;
        case sample::Aov::Depth: return CausticsAov::Depth;
        case sample::Aov::Direct: return CausticsAov::Direct;
        case sample::Aov::Caustics: return CausticsAov::Caustics;
    }
    return CausticsAov::Final;
}

CausticsSettings settingsFromOptions(const sample::CliOptions& o) {
    CausticsSettings s;
    s.mapResolution = o.mapResolution;
    s.raysPerTexel = o.raysPerTexel;
    s.maxSpecularDepth = o.maxDepth;
    s.maxStoredHits = o.maxStoredHits;
    s.filter = o.filter;
    s.filterSecondTypeApart = o.filterSecondTypeApart;
    s.secondType = o.secondType;
    s.mapOccluders = o.mapOccluders;
    s.exposure = o.exposure;
    s.aov = toCausticsAov(o.aov);
    s.seed = o.controls.seed;
    s.sphereRadiusScale = o.controls.sphereRadiusScale;
    s.sphereWorldRadius = o.controls.sphereWorldRadius;
    s.sphereRadiusPolicy = o.controls.sphereRadiusPolicy == sample::SphereRadiusChoice::World
                               ? SphereRadiusPolicy::FixedWorld
                               : SphereRadiusPolicy::PixelFootprint;
    for (const auto& [field, value] : o.settingFields) (void)sample::setSettingsField(s, field, value);   // checked when parsed
    if (o.controls.accumulate > 0) s.filter = false;  // --accumulate averages the unfiltered estimate
    return s;
}

std::string referencePath(const sample::CliOptions& o) {
    std::string stem = o.outPath.empty() ? "caustics" : o.outPath.substr(0, o.outPath.rfind('.'));
    return stem + ".reference.exr";
}

// Every file the run will write is checked before the scene is loaded: a bad path costs nothing.
Status checkOutputs(const sample::CliOptions& o) {
    if (!o.outPath.empty()) CAUSTICS_CHECK(sample::checkWritable("--out", sample::framePath(o.outPath, 0)));
    if (!o.graphDotPath.empty()) CAUSTICS_CHECK(sample::checkWritable("--graph-dot", o.graphDotPath));
    if (o.reference) CAUSTICS_CHECK(sample::checkWritable("--reference", referencePath(o)));
    return okStatus();
}

// --reference: the CPU light tracer (engine/reference) renders the first-type caustics of the same
// view with the same estimator, written beside --out as <stem>.reference.exr (linear cd/m^2).
int writeReference(const sample::CliOptions& o, const scene::Scene& scene, const scene::Camera& camera) {
    reference::ReferenceOptions ro;
    ro.width = o.width;
    ro.height = o.height;
    ro.photonsPerLight = o.referencePhotons;
    ro.maxDepth = o.maxDepth;
    auto image = reference::renderCausticsReference(scene, camera, ro);
    if (!image) {
        std::fprintf(stderr, "caustics-sponza: reference: %s\n", image.message().c_str());
        return 1;
    }
    sample::FloatImage out{image->width, image->height, 3, {}};
    for (const glm::vec3& p : image->pixels) out.pixels.insert(out.pixels.end(), {p.x, p.y, p.z});
    std::string path = referencePath(o);
    if (Status st = sample::writeImage(path, out); !st) {
        std::fprintf(stderr, "caustics-sponza: %s\n", st.message().c_str());
        return 1;
    }
    std::printf("wrote %s (CPU reference, %u photons per light)\n", path.c_str(), o.referencePhotons);
    return 0;
}

void printTimings(const rg::RenderGraph& graph) {
    std::printf("GPU time per pass (median over the frames rendered):\n");
    double total = 0.0;
    for (const auto& pass : graph.desc().passes) {
        auto ms = graph.passTimeMs(pass.name);
        if (!ms) continue;
        total += *ms;
        std::printf("  %-24s %9.3f ms\n", pass.name.c_str(), *ms);
    }
    std::printf("  %-24s %9.3f ms\n", "total", total);
}

int run(const sample::CliOptions& o) {
    if (Status st = checkOutputs(o); !st) {
        std::fprintf(stderr, "caustics-sponza: %s\n", st.message().c_str());
        return 1;
    }
    sample::Script script;   // checked whole before anything is loaded
    if (!o.scriptPath.empty()) {
        auto loaded = sample::loadScript(o.scriptPath);
        if (!loaded) {
            std::fprintf(stderr, "caustics-sponza: %s\n", loaded.message().c_str());
            return 2;
        }
        script = std::move(*loaded);
    }
    auto sceneResult = sample::loadSceneFromOptions(o);
    if (!sceneResult) {
        std::fprintf(stderr, "caustics-sponza: %s\n", sceneResult.message().c_str());
        return 1;
    }
    for (const std::string& w : sample::prepareSceneForRendering(*sceneResult))
        std::fprintf(stderr, "caustics-sponza: warning: %s\n", w.c_str());
    scene::Scene& scene = *sceneResult;
    std::printf("scene: %s%s (%zu instances, %zu lights)\n", scene.name.c_str(),
                scene.isStandIn ? " [generated stand-in, not the real asset]" : "", scene.instances.size(),
                scene.lights.size());
    if (Status st = sample::checkAnimatedLights(o.animation.toggles, scene.lights.size(), "--animate"); !st) {
        std::fprintf(stderr, "caustics-sponza: %s\n", st.message().c_str());
        return 1;
    }

    rhi::DeviceDesc dd;
    dd.backend = *rhi::parseBackend(o.backend);
    dd.enableValidation = o.validation;
    // With --validation every warning or error the layers report makes the run fail (exit 3), so
    // scripted runs and tests can rely on the exit code.
    dd.validationCallback = [](LogLevel level, std::string_view message) {
        if (level == LogLevel::Warning || level == LogLevel::Error) ++gValidationProblems;
        caustics::log(level, message);
    };
    auto device = rhi::createDevice(dd);
    if (!device) {
        std::fprintf(stderr, "caustics-sponza: %s\n", device.message().c_str());
        return 1;
    }
    std::printf("device: %s (%s)\n", (*device)->capabilities().adapterName.c_str(),
                (*device)->capabilities().driverName.c_str());
    if (Status st = sample::checkFrameSize((*device)->capabilities(), o.width, o.height); !st) {
        std::fprintf(stderr, "caustics-sponza: %s\n", st.message().c_str());
        return 1;
    }
    auto gpuScene = scene::GpuScene::create(**device, scene);
    if (!gpuScene) {
        std::fprintf(stderr, "caustics-sponza: %s\n", gpuScene.message().c_str());
        return 1;
    }
    auto module = CausticsModule::create(*device, scene, *gpuScene, settingsFromOptions(o));
    if (!module) {
        std::fprintf(stderr, "caustics-sponza: %s\n", module.message().c_str());
        return 1;
    }
    if (Status fits = sample::checkFrameFitsDevice(**device, **module, o.width, o.height); !fits) {
        std::fprintf(stderr, "caustics-sponza: %s\n", fits.message().c_str());
        return 1;
    }
    // Everything the module holds in one frame, from its frame graph built and sized at this size.
    auto report = sample::moduleFrameReport(**device, **module, o.width, o.height);
    if (!report) {
        std::fprintf(stderr, "caustics-sponza: %s\n", report.message().c_str());
        return 1;
    }
    uint64_t peak = 0, sceneBytes = 0;
    for (const MemoryEntry& e : *report) {
        if (e.kind == MemoryKind::FramePeak) peak += e.bytes;
        if (isHostSceneMemory(e)) sceneBytes += e.bytes;
    }
    const uint64_t held = moduleFrameBytes(*report);
    std::printf("frame memory: %.1f MiB for %ux%u: the module holds %.1f MiB (persistent %.1f + peak transient %.1f, "
                "from its frame graph), the scene %.1f MiB\n",
                double(held + sceneBytes) / 1048576.0, o.width, o.height, double(held) / 1048576.0,
                double(held - peak) / 1048576.0, double(peak) / 1048576.0, double(sceneBytes) / 1048576.0);
    if (o.window) return sample::runViewer(*device, scene, *gpuScene, *module, o, script);

    auto renderer = sample::FrameRenderer::create(*device, **module, o.width, o.height);
    if (!renderer) {
        std::fprintf(stderr, "caustics-sponza: %s\n", renderer.message().c_str());
        return 1;
    }
    scene::Camera camera = sample::cameraFromOptions(scene, o);
    auto still = o.animation.frames > 0 ? sample::renderAnimation(**renderer, scene, camera, o)
                                        : sample::renderStill(**renderer, camera, o);
    if (!still) {
        std::fprintf(stderr, "caustics-sponza: %s\n", still.message().c_str());
        return 1;
    }
    if (o.controls.accumulate > 0)
        std::printf("accumulated %u unfiltered frames (seed %u)\n", o.controls.accumulate, o.controls.seed);
    printTimings((*renderer)->graph());
    if (!o.graphDotPath.empty()) {
        if (Status st = sample::writeTextFile("--graph-dot", o.graphDotPath, (*renderer)->graph().printGraphviz()); !st) {
            std::fprintf(stderr, "caustics-sponza: %s\n", st.message().c_str());
            return 1;
        }
        std::printf("wrote %s\n", o.graphDotPath.c_str());
    }
    if (!o.outPath.empty() && o.outPath.find(sample::kFrameToken) == std::string::npos) {
        const sample::FrameImages& img = *still;
        if (Status st = sample::writeFiniteRenderedImage(o.outPath, img.width, img.height, img.display, img.hdr); !st) {
            std::fprintf(stderr, "caustics-sponza: %s\n", st.message().c_str());
            return 1;
        }
        std::printf("wrote %s (%ux%u, aov %s)\n", o.outPath.c_str(), img.width, img.height, sample::aovName(o.aov));
    }
    if (o.reference) return writeReference(o, scene, camera);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv, argv + argc);
    auto options = sample::parseCliOptions(args);
    if (!options) {
        std::fprintf(stderr, "caustics-sponza: %s\n%s", options.message().c_str(), sample::cliUsage());
        return 2;
    }
    if (options->help) {
        std::printf("%s", sample::cliUsage());
        return 0;
    }
    int code = run(*options);
    if (code == 0 && gValidationProblems > 0) {
        std::fprintf(stderr, "caustics-sponza: %u validation warnings/errors (see above)\n", gValidationProblems.load());
        return 3;
    }
    return code;
}
