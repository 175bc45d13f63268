// `sweep` mode: the paper's section-4 measurements (Figures 9, 11, 13) and more, as CSV under --out:
//   timings.csv  one row per run: frame and per-pass medians and the caustic counters, varying
//                lights (extra ring lights 0..8, camera on the caustics and turned away: Figure 9; and
//                0..8 "culled" ring lights aimed away from every specular object, which the map
//                planner culls: view column "culled"),
//                rays per texel (Figure 11), depth (Figure 13), map size and image size; backward_ms
//                includes caustics.specularPixels and spheres_ms caustics.sphereCount (gather_ms already
//                includes caustics.gatherGrid)
//                and the forward pass's ray segments per second next to the incoherent ray ceiling of
//                the same scene measured in the same run (ray_rates.h: --width x --height rays from
//                uniform points of the scene's box in uniform directions against the scene TLAS), and
//                their ratio (issue 11's target: >= 0.6 at >= 8 rays per texel); ceiling.csv has it alone
//   memory.csv   every caustic transient (render graph, before aliasing) and every persistent resource
//                (CausticsModule::memoryReport()) of each run, its size and kind, and a "total" row
//   quality.csv  relative L1 of the caustic image against a converged reference (16 rays per texel x
//                --reference-frames frames, unfiltered) next to the time, filter off and on
// Every other setting stays at the flags' values (paper defaults). scripts/plot_bench.py plots them.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <tuple>
#include <utility>

#include "bench_gpu.h"
#include "bench_measure.h"
#include "bench_modes.h"
#include "ray_rates.h"

namespace caustics::bench {
namespace {

struct Run {
    std::string sweep, value;
    BenchView view = BenchView::Visible;
    uint32_t extraLights = 0;
    uint32_t culledLights = 0;        // ring lights whose cone holds no specular object
    bool culledSeries = false;        // the lights sweep's "culled" series (view column "culled")
    uint32_t width = 0, height = 0;
    CausticsSettings settings;
    const std::vector<float>* reference = nullptr;   // quality row against it when set
};

const char* runViewName(const Run& r) { return r.culledSeries ? "culled" : viewName(r.view); }

class SweepWriter {
public:
    explicit SweepWriter(const std::string& dir)
        : timings_(dir + "/timings.csv"), memory_(dir + "/memory.csv"), quality_(dir + "/quality.csv") {
        timings_ << "sweep,value,view,scene,width,height,lights,maps,map_size,rays_per_texel,depth,filter,frame_ms,"
                    "caustics_ms,maps_ms,emitters_ms,forward_ms,backward_ms,spheres_ms,gather_ms,filter_ms,photons,"
                    "texels_emitting,texels_dispatched,segments,spheres,stored_hits,hits_offered,overflow,"
                    "transient_bytes,transient_heap_bytes,specular_pixels,backward_launches,sphere_capacity,spheres_dropped,"
                    "forward_msegments_per_s,incoherent_ceiling_mrays_per_s,forward_fraction_of_ceiling,persistent_bytes\n";
        memory_ << "sweep,value,view,resource,bytes,kind\n";
        quality_ << "sweep,value,rays_per_texel,depth,filter,caustics_ms,frame_ms,relative_l1\n";
    }
    bool ok() const { return timings_.good() && memory_.good() && quality_.good(); }
    void setCeiling(double megaRaysPerSecond) { ceilingMrays_ = megaRaysPerSecond; }

    void write(const Run& r, const scene::Scene& sc, const Measurement& m) {
        const CausticsSettings& s = r.settings;
        const char* view = runViewName(r);
        uint64_t transientBytes = 0;
        auto memoryRow = [&](const std::string& name, uint64_t bytes, const char* kind) {
            memory_ << r.sweep << ',' << r.value << ',' << view << ',' << name << ',' << bytes << ',' << kind << '\n';
        };
        for (const TransientMemory& t : m.transients) {
            transientBytes += t.bytes;
            memoryRow(t.name, t.bytes, memoryKindName(MemoryKind::Transient));
        }
        const uint64_t persistentBytes = totalBytes(m.persistent);
        for (const MemoryEntry& e : m.persistent) memoryRow(e.name, e.bytes, memoryKindName(e.kind));
        memoryRow("total", transientBytes + persistentBytes, "all");
        std::string sceneName = sc.name;   // plain CSV: no quoting needed
        for (char& c : sceneName)
            if (c == ',' || c == '"') c = ';';
        timings_ << r.sweep << ',' << r.value << ',' << view << ',' << sceneName << ',' << r.width << ','
                 << r.height << ',' << sc.lights.size() << ',' << m.maps << ',' << s.mapResolution << ','
                 << s.raysPerTexel << ',' << s.maxSpecularDepth << ',' << (s.filter ? "on" : "off") << ',' << m.frameMs
                 << ',' << m.causticsMs << ',' << m.passTime("caustics.maps") << ',' << m.passTime("caustics.emitters")
                 << ',' << m.passTime("caustics.forward") << ','
                 << m.passTime("caustics.backward") + m.passTime("caustics.specularPixels") << ','
                 << m.passTime("caustics.sphereBlas") + m.passTime("caustics.spheres") + m.passTime("caustics.sphereCount") << ','
                 << m.passTime("caustics.gather") << ','
                 << m.passTime("caustics.temporal") + m.passTime("caustics.atrous") + m.passTime("caustics.history")
                 << ',' << m.photons << ',' << m.emitterTexels << ',' << m.dispatchedTexels << ',' << m.segments << ','
                 << m.spheres << ',' << m.storedHits << ',' << m.hitAttempts << ',' << (m.hitAttempts > m.storedHits)
                 << ',' << transientBytes << ',' << m.transientHeapBytes << ',' << m.specularPixels << ','
                 << m.backwardLaunches << ',' << m.sphereCapacity << ',' << m.spheresDropped;
        const double forwardMs = m.passTime("caustics.forward");
        const double segmentsPerS = forwardMs > 0.0 ? double(m.segments) / (forwardMs * 1e3) : 0.0;
        timings_ << ',' << segmentsPerS << ',' << ceilingMrays_ << ','
                 << (ceilingMrays_ > 0.0 ? segmentsPerS / ceilingMrays_ : 0.0) << ',' << persistentBytes << '\n';
        if (r.reference)
            quality_ << r.sweep << ',' << r.value << ',' << s.raysPerTexel << ',' << s.maxSpecularDepth << ','
                     << (s.filter ? "on" : "off") << ',' << m.causticsMs << ',' << m.frameMs << ','
                     << relativeL1(m.caustics, *r.reference) << '\n';
        timings_.flush();
        memory_.flush();
        quality_.flush();
    }

private:
    std::ofstream timings_, memory_, quality_;
    double ceilingMrays_ = 0.0;
};

bool wanted(const BenchOptions& o, const char* sweep) {
    std::stringstream list(o.sweeps);
    for (std::string item; std::getline(list, item, ',');)
        if (item == sweep) return true;
    return false;
}

template <typename T>
std::string text(T v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

std::vector<Run> planRuns(const BenchOptions& o, const std::vector<float>* reference4, const std::vector<float>* reference16) {
    const CausticsSettings base = benchSettings(o);
    std::vector<Run> runs;
    auto add = [&](const char* sweep, std::string value, const std::function<void(Run&)>& change) {
        Run r{sweep, std::move(value), BenchView::Visible, o.extraLights, 0, false, o.width, o.height, base, nullptr};
        change(r);
        runs.push_back(r);
    };
    if (wanted(o, "lights"))
        for (BenchView view : {BenchView::Visible, BenchView::Away})
            for (uint32_t extra : {0u, 1u, 2u, 4u, 8u})
                add("lights", text(extra), [&](Run& r) { r.view = view; r.extraLights = extra; });
    if (wanted(o, "lights"))
        for (uint32_t culled : {0u, 1u, 2u, 4u, 8u})
            add("lights", text(culled), [&](Run& r) {
                r.culledLights = culled;
                r.culledSeries = true;
            });
    if (wanted(o, "rays"))
        for (bool filter : {false, true})
            for (float rays : {0.25f, 0.5f, 0.75f, 1.0f, 2.0f, 4.0f, 8.0f, 25.0f})
                add("rays", text(rays), [&](Run& r) {
                    r.settings.raysPerTexel = rays;
                    r.settings.filter = filter;
                    r.settings.maxSpecularDepth = 4;
                    r.reference = reference4;
                });
    if (wanted(o, "depth"))
        for (uint32_t depth : {1u, 2u, 3u, 4u, 8u, 16u})
            add("depth", text(depth), [&](Run& r) {
                r.settings.maxSpecularDepth = depth;
                r.reference = reference16;
            });
    if (wanted(o, "map"))
        for (uint32_t map : {256u, 512u, 1024u, 2048u})
            add("map", text(map), [&](Run& r) { r.settings.mapResolution = map; });
    if (wanted(o, "image"))
        for (auto [w, h] : {std::pair{1280u, 720u}, {1920u, 1080u}, {2560u, 1440u}, {3840u, 2160u}})
            add("image", text(w) + "x" + text(h), [&](Run& r) {
                r.width = w;
                r.height = h;
            });
    return runs;
}

int fail(const std::string& what) {
    std::fprintf(stderr, "caustics-bench sweep: %s\n", what.c_str());
    return 1;
}

}  // namespace

int runSweepMode(const BenchOptions& o) {
    std::error_code ec;
    std::filesystem::create_directories(o.outDir, ec);
    if (ec) return fail("--out " + o.outDir + ": " + ec.message());
    SweepWriter writer(o.outDir);
    if (!writer.ok()) return fail("--out " + o.outDir + ": cannot write the CSV files there");
    auto device = createBenchDevice(o);
    if (!device) return fail(device.message());
    const std::string sceneName = o.scenes.substr(0, o.scenes.find(','));
    std::printf("caustics-bench sweep on %s, scene %s, %ux%u, writing %s/{timings,memory,quality}.csv\n",
                device.value()->capabilities().adapterName.c_str(), sceneName.c_str(), o.width, o.height,
                o.outDir.c_str());

    // One session (scene + module) per number of extra lights; settings and image size change in it.
    std::unique_ptr<BenchSession> session;
    std::pair<uint32_t, uint32_t> sessionLights{~0u, ~0u};   // extra, culled
    auto sessionFor = [&](uint32_t extraLights, uint32_t culledLights = 0) -> Result<BenchSession*> {
        if (session && sessionLights == std::pair{extraLights, culledLights}) return session.get();
        session.reset();
        CAUSTICS_TRY(scene::Scene sc, loadBenchScene(sceneName, extraLights, culledLights));
        CAUSTICS_TRY(session, BenchSession::create(device.value(), std::move(sc), benchSettings(o)));
        sessionLights = {extraLights, culledLights};
        return session.get();
    };

    // The incoherent ray ceiling of this scene (its own TLAS and triangles), measured once: extra and
    // culled lights do not change the geometry.
    {
        auto s = sessionFor(o.extraLights);
        if (!s) return fail(s.message());
        RayFrameConstants constants{};
        sceneBox(s.value()->scene, constants.boundsMin, constants.boundsMax);
        auto rates = measureRayRates(*device.value(), s.value()->gpu->tlas, constants, o.width, o.height, o, {"incoherent"});
        if (!rates) return fail("ray ceiling: " + rates.message());
        const RayRate& ceiling = rates->front();
        writer.setCeiling(ceiling.megaRaysPerSecond());
        std::ofstream(o.outDir + "/ceiling.csv") << "scene,rays,median_ms,mrays_per_s,hit_fraction\n"
                                                  << sceneName << ',' << ceiling.raysPerFrame << ',' << ceiling.medianMs
                                                  << ',' << ceiling.megaRaysPerSecond() << ',' << ceiling.hitFraction
                                                  << '\n';
        std::printf("  incoherent ceiling on the scene TLAS: %.2f M rays/s (%.1f %% hit)\n",
                    ceiling.megaRaysPerSecond(), 100.0 * ceiling.hitFraction);
    }

    // Converged references of the quality rows (depth 4 for the rays sweep, 16 for the depth sweep).
    std::vector<float> reference4, reference16;
    CausticsSettings refSettings = benchSettings(o);
    for (auto [depth, out, sweep] : {std::tuple{4u, &reference4, "rays"}, {16u, &reference16, "depth"}}) {
        if (!wanted(o, sweep)) continue;
        refSettings.maxSpecularDepth = depth;
        auto s = sessionFor(o.extraLights);
        if (!s) return fail(s.message());
        auto ref = causticReference(device.value(), *s.value(), refSettings, o.width, o.height, o.referenceFrames);
        if (!ref) return fail("reference: " + ref.message());
        *out = std::move(ref.value());
    }

    for (const Run& r : planRuns(o, &reference4, &reference16)) {
        if (Status ok = r.settings.validate(); !ok) return fail(r.sweep + " " + r.value + ": " + ok.message());
        auto s = sessionFor(r.extraLights, r.culledLights);
        if (!s) return fail(s.message());
        auto m = measure(device.value(), *s.value(), r.settings, r.width, r.height, r.view, o, r.reference != nullptr);
        if (!m) return fail(r.sweep + " " + r.value + ": " + m.message());
        writer.write(r, s.value()->scene, m.value());
        std::printf("  %-6s %-10s %-7s caustics %8.3f ms  frame %8.3f ms\n", r.sweep.c_str(), r.value.c_str(),
                    runViewName(r), m->causticsMs, m->frameMs);
    }
    return 0;
}

}  // namespace caustics::bench
