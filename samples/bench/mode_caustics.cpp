// `caustics` and `frame` modes: per-pass GPU time medians of one configuration (the flags; defaults are
// the paper's section 4: 512x512 maps, 1 ray per texel, depth 4, filter off) on each scene of --scene
// (built-in generated stand-ins, labelled as such), through CausticsModule (public API only), with the
// caustic counters of the last frame. `caustics` lists the caustic passes, `frame` every pass.
#include <cstdio>
#include <sstream>

#include "bench_gpu.h"
#include "bench_measure.h"
#include "bench_modes.h"

namespace caustics::bench {
namespace {

int fail(const char* mode, const std::string& what) {
    std::fprintf(stderr, "caustics-bench %s: %s\n", mode, what.c_str());
    return 1;
}

void printCounters(const Measurement& m) {
    std::printf("  photon paths %llu, ray segments %llu, emitting texels %llu of %llu dispatched (%.1f %%)\n",
                (unsigned long long)m.photons, (unsigned long long)m.segments, (unsigned long long)m.emitterTexels,
                (unsigned long long)m.dispatchedTexels,
                m.dispatchedTexels ? 100.0 * double(m.emitterTexels) / double(m.dispatchedTexels) : 0.0);
    std::printf("  specular pixels %llu, backward launches %llu, spheres %llu (dropped %llu), sphere capacity %llu\n",
                (unsigned long long)m.specularPixels, (unsigned long long)m.backwardLaunches,
                (unsigned long long)m.spheres, (unsigned long long)m.spheresDropped, (unsigned long long)m.sphereCapacity);
    std::printf("  stored hits %llu (offered %llu%s), gather pairs %llu\n", (unsigned long long)m.storedHits,
                (unsigned long long)m.hitAttempts, m.hitAttempts > m.storedHits ? ", OVERFLOW" : "",
                (unsigned long long)m.gatherPairs);
    if (const double forwardMs = m.passTime("caustics.forward"); forwardMs > 0.0)
        std::printf("  forward: %.1f M paths/s, %.1f M segments/s\n", double(m.photons) / (forwardMs * 1e3),
                    double(m.segments) / (forwardMs * 1e3));
    std::printf("  caustic transients: %.1f MiB in a %.1f MiB heap (aliased)\n", [&] {
        uint64_t sum = 0;
        for (const TransientMemory& t : m.transients) sum += t.bytes;
        return double(sum) / (1 << 20);
    }(), double(m.transientHeapBytes) / (1 << 20));
}

// The caustic filter's passes (passes/caustic_filter: the tile passes, temporal, variance, a-trous,
// filterOutput, each once more with ".secondType" appended when the second type is filtered apart, and
// then filterCombine; not caustics.resolve, which runs with the filter off too, nor the second type's
// guides, written by the backward trace).
double filterMs(const Measurement& m) {
    double sum = 0.0;
    for (const auto& [pass, ms] : m.passMs)
        for (const char* prefix : {"caustics.filterTiles", "caustics.temporal", "caustics.variance", "caustics.atrous.",
                                   "caustics.filterOutput", "caustics.filterCombine"})
            if (pass.rfind(prefix, 0) == 0) sum += ms;
    return sum;
}

int runMeasuredMode(const BenchOptions& o, bool everyPass) {
    const char* mode = everyPass ? "frame" : "caustics";
    auto device = createBenchDevice(o);
    if (!device) return fail(mode, device.message());
    CausticsSettings settings = benchSettings(o);
    if (Status ok = settings.validate(); !ok) return fail(mode, ok.message());
    std::printf("caustics-bench %s on %s (%s), median of %u frames after %u warm-up\n", mode,
                device.value()->capabilities().adapterName.c_str(), device.value()->capabilities().driverName.c_str(),
                o.frames, warmupFrames(o, settings));
    std::stringstream scenes(o.scenes);
    for (std::string name; std::getline(scenes, name, ',');) {
        auto sc = loadBenchScene(name, o.extraLights);
        if (!sc) return fail(mode, name + ": " + sc.message());
        auto session = BenchSession::create(device.value(), sc.value(), settings);
        if (!session) return fail(mode, name + ": " + session.message());
        const BenchView view = o.viewAway ? BenchView::Away : BenchView::Visible;
        auto m = measure(device.value(), *session.value(), settings, o.width, o.height, view, o, false);
        if (!m) return fail(mode, name + ": " + m.message());
        std::printf("\nscene %s%s: %zu lights, %u maps, %ux%u, map %u, %.2f rays/texel, depth %u, filter %s, view %s\n",
                    sc->name.c_str(), sc->isStandIn ? " [generated stand-in]" : "", sc->lights.size(), m->maps, o.width,
                    o.height, settings.mapResolution, settings.raysPerTexel, settings.maxSpecularDepth,
                    settings.filter ? "on" : "off", viewName(view));
        for (const auto& [pass, ms] : m->passMs)
            if (everyPass || pass.rfind("caustics.", 0) == 0) std::printf("  %-22s %9.3f ms\n", pass.c_str(), ms);
        if (settings.filter) std::printf("  %-22s %9.3f ms\n", "filter total", filterMs(m.value()));
        std::printf("  %-22s %9.3f ms\n  %-22s %9.3f ms\n", "caustics total", m->causticsMs, "frame (all passes)",
                    m->frameMs);
        printCounters(m.value());
    }
    return 0;
}

}  // namespace

int runCausticsMode(const BenchOptions& options) { return runMeasuredMode(options, false); }
int runFrameMode(const BenchOptions& options) { return runMeasuredMode(options, true); }

}  // namespace caustics::bench
