// caustics-bench level: the game-level stand-in (scene::makeLevelScene) as a game would use it
// (docs/caustics.md, "Photon budget"). Writes under --out:
//   level_sweep.csv   object count, level extent and photon budget sweeps: layers in view, clusters
//                     hidden, photons, caustic and forward GPU time (medians)
//   level_target.csv  60 frames of a camera moving over the level at --width x --height and twice that
//                     (1080p and 4K by default), under a GPU-time target
//                     (--time-target, default 1 ms): each frame's budget and measured caustic time, then
//                     the seed-to-seed noise of the caustic image at the budget reached
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>

#include "bench_frame.h"
#include "bench_gpu.h"
#include "bench_measure.h"
#include "bench_modes.h"
#include "caustics/caustic_map_plan.h"
#include "caustics/caustic_passes.h"
#include "caustics/scene/builtin_scenes.h"

namespace caustics::bench {
namespace {

int fail(const std::string& what) {
    std::fprintf(stderr, "caustics-bench level: %s\n", what.c_str());
    return 1;
}

// The camera of frame f of 60: circles the level's first objects at 9 m, 4 m up, a quarter turn.
scene::Camera movingCamera(const scene::Scene& level, uint32_t frame) {
    scene::Camera cam = level.cameras.front();
    const float angle = 0.7f + 1.5f * float(frame) / 60.0f;
    const glm::vec3 centre = cam.target;
    cam.eye = centre + glm::vec3(9.0f * std::cos(angle), 4.0f, 9.0f * std::sin(angle));
    return cam;
}

struct PlanCounts {
    size_t layers = 0;
    uint32_t hidden = 0;
};

PlanCounts planCounts(const scene::Scene& level, const scene::Camera& cam, uint32_t w, uint32_t h, float reach) {
    auto constants = makeCameraConstants(cam, w, h, 0);
    if (!constants) return {};
    const CausticView view = causticViewOf(constants.value());
    CausticPlanOptions o;
    o.view = &view;
    o.receiverReach = reach;
    CausticMapPlan p = planCausticMaps(level, computeSpecularBounds(level), o);
    return {p.maps.size(), p.hiddenClusters};
}

uint64_t photonsOf(const std::vector<uint32_t>& stats) {
    uint64_t n = 0;
    for (uint32_t l = 0; l < kMaxCausticLights; ++l) n += stats[kStatRaysPerLight + l];
    return n;
}

}  // namespace

int runLevelMode(const BenchOptions& o) {
    std::error_code ec;
    std::filesystem::create_directories(o.outDir, ec);
    if (ec) return fail("--out " + o.outDir + ": " + ec.message());
    auto device = createBenchDevice(o);
    if (!device) return fail(device.message());
    std::ofstream sweep(o.outDir + "/level_sweep.csv"), target(o.outDir + "/level_target.csv");
    if (!sweep || !target) return fail("--out " + o.outDir + ": cannot write the CSV files there");
    std::printf("caustics-bench level on %s, writing %s/level_{sweep,target}.csv (level: generated stand-in)\n",
                device.value()->capabilities().adapterName.c_str(), o.outDir.c_str());
    const uint32_t budget = o.photons ? o.photons : (1u << 18);

    sweep << "sweep,value,objects,extent_m,budget,width,height,layers,hidden_clusters,photons,caustics_ms,forward_ms,maps_ms\n";
    auto row = [&](const char* name, const std::string& value, const scene::LevelSceneDesc& d, uint32_t photons) -> Status {
        CausticsSettings s = benchSettings(o);
        s.photonsPerFrame = photons;
        s.causticTimeTargetMs = 0.0f;
        CAUSTICS_TRY(auto session, BenchSession::create(device.value(), scene::makeLevelScene(d), s));
        CAUSTICS_TRY(Measurement m, measure(device.value(), *session, s, o.width, o.height, BenchView::Visible, o, false));
        const PlanCounts pc = planCounts(session->scene, benchCamera(session->scene, BenchView::Visible), o.width, o.height,
                                         s.causticReceiverReach);
        sweep << name << ',' << value << ',' << d.objects << ',' << d.extent << ',' << photons << ',' << o.width << ','
              << o.height << ',' << pc.layers << ',' << pc.hidden << ',' << m.photons << ',' << m.causticsMs << ','
              << m.passTime("caustics.forward") << ',' << m.passTime("caustics.maps") << '\n';
        std::printf("  %-8s %-8s layers %zu hidden %u photons %llu caustics %.3f ms\n", name, value.c_str(), pc.layers,
                    pc.hidden, (unsigned long long)m.photons, m.causticsMs);
        return okStatus();
    };
    for (uint32_t objects : {12u, 24u, 48u, 96u}) {
        scene::LevelSceneDesc d;
        d.objects = objects;
        if (auto st = row("objects", std::to_string(objects), d, budget); !st) return fail(st.message());
    }
    for (float extent : {50.0f, 100.0f, 200.0f, 400.0f}) {
        scene::LevelSceneDesc d;
        d.extent = extent;
        if (auto st = row("extent", std::to_string(int(extent)), d, budget); !st) return fail(st.message());
    }
    for (uint32_t photons : {1u << 16, 1u << 17, 1u << 18, 1u << 19, 1u << 20}) {
        if (auto st = row("budget", std::to_string(photons), scene::LevelSceneDesc{}, photons); !st)
            return fail(st.message());
    }
    sweep.flush();

    // The time target over a moving camera, as the module steers it from its own timestamps.
    const float targetMs = o.timeTargetMs > 0.0f ? o.timeTargetMs : 1.0f;
    target << "width,height,frame,budget,caustics_ms,target_ms\n";
    for (auto [w, h] : {std::pair{o.width, o.height}, {2 * o.width, 2 * o.height}}) {
        CausticsSettings s = benchSettings(o);
        s.causticTimeTargetMs = targetMs;
        s.photonsPerFrame = budget;
        auto session = BenchSession::create(device.value(), scene::makeLevelScene(), s);
        if (!session) return fail(session.message());
        auto frames = BenchFrames::create(device.value(), *session.value()->module, w, h);
        if (!frames) return fail(frames.message());
        uint32_t within = 0, counted = 0;
        uint64_t lastPhotons = 0;
        for (uint32_t f = 0; f < 60; ++f) {
            if (auto st = frames.value()->render(movingCamera(session.value()->scene, f), f, false); !st) return fail(st.message());
            const double ms = frames.value()->graph().timings().latestTotalMs("caustics.").value_or(0.0);
            lastPhotons = photonsOf(frames.value()->stats());
            target << w << ',' << h << ',' << f << ',' << lastPhotons << ',' << ms << ',' << targetMs << '\n';
            if (f >= 20) {   // after the controller settled from its start value
                ++counted;
                if (std::abs(ms - targetMs) <= 0.15 * targetMs) ++within;
            }
        }
        // Noise at the budget reached: two seeds, same frame, relative L1 of the caustic radiance.
        s.causticTimeTargetMs = 0.0f;
        s.photonsPerFrame = uint32_t(std::max<uint64_t>(lastPhotons, 1));
        std::vector<float> images[2];
        for (uint32_t seed : {1u, 2u}) {
            s.seed = seed;
            if (auto st = session.value()->module->setSettings(s); !st) return fail(st.message());
            if (auto st = frames.value()->render(movingCamera(session.value()->scene, 59), 60 + seed, true); !st)
                return fail(st.message());
            images[seed - 1] = frames.value()->caustics();
        }
        const double noise = relativeL1(images[0], images[1]);
        std::printf("  target %.2f ms at %ux%u: %u of %u frames (20..59) within 15 %%, last budget %llu photons, "
                    "seed-to-seed L1 %.3f\n",
                    targetMs, w, h, within, counted, (unsigned long long)lastPhotons, noise);
        target << "# " << w << 'x' << h << " within15=" << within << '/' << counted << " photons=" << lastPhotons
               << " noise_l1=" << noise << '\n';
    }
    return 0;
}

}  // namespace caustics::bench
