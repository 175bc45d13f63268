#include "bench_options.h"

#include <charconv>
#include <string_view>

#include "bench_modes.h"

namespace caustics::bench {
namespace {

Result<uint32_t> parseCount(std::string_view flag, std::string_view text) {
    uint32_t value = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || value == 0)
        return makeError(std::string(flag) + ": expected a positive integer, got '" + std::string(text) + "'");
    return value;
}

}  // namespace

std::string benchUsage() {
    std::string text = "usage: caustics-bench <mode> [--width W] [--height H] [--frames N] [--triangles T]\n"
                       "                      [--backend vulkan|d3d12] [--validation]\nmodes:\n";
    for (const BenchMode& mode : benchModes()) text += "  " + std::string(mode.name) + "  " + mode.summary + "\n";
    return text;
}

Result<BenchOptions> parseBenchOptions(int argc, char** argv) {
    BenchOptions options;
    if (argc < 2) return makeError("no mode given");
    options.mode = argv[1];
    for (int i = 2; i < argc; ++i) {
        const std::string_view flag = argv[i];
        if (flag == "--validation") {
            options.validation = true;
            continue;
        }
        if (i + 1 >= argc) return makeError(std::string(flag) + ": missing value");
        const std::string_view value = argv[++i];
        if (flag == "--backend") {
            auto backend = rhi::parseBackend(value);
            if (!backend) return makeError("--backend: expected vulkan or d3d12, got '" + std::string(value) + "'");
            options.backend = *backend;
            continue;
        }
        uint32_t* target = flag == "--width"       ? &options.width
                           : flag == "--height"    ? &options.height
                           : flag == "--frames"    ? &options.frames
                           : flag == "--triangles" ? &options.triangles
                                                   : nullptr;
        if (!target) return makeError("unknown option '" + std::string(flag) + "'");
        CAUSTICS_TRY(*target, parseCount(flag, value));
    }
    return options;
}

}  // namespace caustics::bench
