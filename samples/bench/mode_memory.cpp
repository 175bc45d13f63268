// `memory` mode: what CausticsModule holds at 1280x720, 1920x1080, 2560x1440 and 3840x2160 (the first
// scene of --scene, the flags' settings with the second type on), filter on and off. Each frame graph
// is built and compiled against the device's memory requirements, never executed (docs/embedding.md
// "Memory"): the persistent resources it sized (memoryReport) plus its transients' aliased peak
// (appendFrameMemory), the host's scene apart. Shares are differences between runs: the filter's
// (filter on - off), the caustic passes' without the filter (filter off - caustics off: what they add
// to the module's own G-buffer, direct lighting and composite, the "frame" column). The filter's history
// pool starts at a quarter of the view's tiles and grows with the caustics' coverage once frames run
// (docs/caustics.md "Memory"), so "full share" is the filter's share with the pool at the whole view: what
// a view whose caustics cover the screen (the built-in table scene after a few frames) holds. With --out,
// every entry goes to memory.csv (size, run, resource, bytes, kind).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "bench_gpu.h"
#include "bench_measure.h"
#include "bench_modes.h"
#include "caustics/render_graph/memory_sizer.h"

namespace caustics::bench {
namespace {

int fail(const std::string& what) {
    std::fprintf(stderr, "caustics-bench memory: %s\n", what.c_str());
    return 1;
}

double mib(uint64_t bytes) { return double(bytes) / 1048576.0; }

// The module's memory for one frame graph at width x height, built and compiled (not executed).
Result<std::vector<MemoryEntry>> frameMemory(rhi::IDevice& device, BenchSession& session, uint32_t width,
                                             uint32_t height) {
    rg::RenderGraph graph;
    FrameInputs in;
    in.camera = cameraViewMatrices(benchCamera(session.scene, BenchView::Visible), width, height);
    in.width = width;
    in.height = height;
    CAUSTICS_TRY(FrameOutputs out, session.module->addPasses(graph, in));
    graph.markOutput(out.display, rhi::ResourceState::CopySource);
    graph.markOutput(out.hdr, rhi::ResourceState::CopySource);
    if (out.causticStats.valid()) graph.markOutput(out.causticStats, rhi::ResourceState::CopySource);
    CAUSTICS_CHECK(graph.compile(rg::DeviceMemorySizer(device)));
    std::vector<MemoryEntry> report = session.module->memoryReport();
    appendFrameMemory(graph, report);
    return report;
}

uint64_t hostSceneBytes(const std::vector<MemoryEntry>& report) {
    uint64_t sum = 0;
    for (const MemoryEntry& e : report)
        if (isHostSceneMemory(e)) sum += e.bytes;
    return sum;
}

}  // namespace

int runMemoryMode(const BenchOptions& o) {
    auto device = createBenchDevice(o);
    if (!device) return fail(device.message());
    CausticsSettings settings = benchSettings(o);
    settings.secondType = true;
    if (Status ok = settings.validate(); !ok) return fail(ok.message());
    const std::string name = o.scenes.substr(0, o.scenes.find(','));
    auto sc = loadBenchScene(name, o.extraLights);
    if (!sc) return fail(name + ": " + sc.message());
    std::ofstream csv;
    if (!o.outDir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(o.outDir, ec);
        csv.open(o.outDir + "/memory.csv");
        if (!csv) return fail("cannot write " + o.outDir + "/memory.csv");
        csv << "width,height,run,resource,bytes,kind\n";
    }
    std::printf("caustics-bench memory on %s (%s), scene %s%s, map %u, second type on; graphs built and sized, "
                "not executed\n",
                device.value()->capabilities().adapterName.c_str(), device.value()->capabilities().driverName.c_str(),
                sc->name.c_str(), sc->isStandIn ? " [generated stand-in]" : "", settings.mapResolution);
    std::printf("%-10s %12s %12s %12s %12s %12s %12s %12s %12s %12s\n", "size", "persistent", "peak trans.", "module",
                "filter off", "filter share", "full share", "caustics", "frame", "host scene");
    constexpr uint32_t kSizes[4][2] = {{1280, 720}, {1920, 1080}, {2560, 1440}, {3840, 2160}};
    std::vector<std::vector<MemoryEntry>> detail;
    for (const auto& size : kSizes) {
        // Runs: 3 filter on with the pool at the whole view, 2 filter on, 1 filter off, 0 caustics off.
        const char* kRunNames[4] = {"caustics_off", "filter_off", "filter_on", "filter_on_full_pool"};
        uint64_t module[4] = {0, 0, 0, 0}, persistent = 0, peak = 0, host = 0;
        const uint32_t startPool = settings.filterPoolTiles;
        for (int run = 3; run >= 0; --run) {
            const bool reported = run == 2;   // the filter-on run whose entries and peak are printed
            settings.filter = run >= 2;
            settings.causticsEnabled = run > 0;
            settings.filterPoolTiles = run == 3 ? CausticsSettings::kMaxFilterPoolTiles : startPool;   // clamped to the view's tiles
            // A fresh module per run: the sphere allocation and history start from this size.
            auto session = BenchSession::create(device.value(), sc.value(), settings);
            if (!session) return fail(session.message());
            auto report = frameMemory(**device, **session, size[0], size[1]);
            if (!report) return fail(report.message());
            module[run] = moduleFrameBytes(*report);
            if (run == 1 && size[0] == o.width && size[1] == o.height) detail.push_back(*report);
            if (reported) {
                host = hostSceneBytes(*report);
                for (const MemoryEntry& e : *report) {
                    if (e.kind == MemoryKind::FramePeak) peak += e.bytes;
                    else if (e.kind == MemoryKind::Persistent && !isHostSceneMemory(e)) persistent += e.bytes;
                }
                if (size[0] == o.width && size[1] == o.height) detail.push_back(*report);
            }
            for (const MemoryEntry& e : *report)
                if (csv) csv << size[0] << ',' << size[1] << ',' << kRunNames[run] << ',' << e.name << ',' << e.bytes << ','
                             << memoryKindName(e.kind) << '\n';
        }
        std::printf("%4ux%-5u %8.1f MiB %8.1f MiB %8.1f MiB %8.1f MiB %8.1f MiB %8.1f MiB %8.1f MiB %8.1f MiB %8.1f MiB\n",
                    size[0], size[1], mib(persistent), mib(peak), mib(module[2]), mib(module[1]), mib(module[2] - module[1]),
                    mib(module[3] - module[1]), mib(module[1] - module[0]), mib(module[0]), mib(host));
    }
    // --width/--height pick the size whose entries are listed (default 1920x1080).
    for (size_t i = 0; i < detail.size(); ++i) {
        std::printf("\n%ux%u, filter %s, every entry (transients before aliasing; the peak is their aliased heap):\n",
                    o.width, o.height, i == 0 ? "on" : "off");
        for (const MemoryEntry& e : detail[i])
            std::printf("  %-44s %10.2f MiB  %s%s\n", e.name.c_str(), mib(e.bytes), memoryKindName(e.kind),
                        isHostSceneMemory(e) ? " (host scene)" : "");
    }
    return 0;
}

}  // namespace caustics::bench
