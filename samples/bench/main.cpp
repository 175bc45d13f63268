// caustics-bench: GPU timings with GPU timestamps, medians over many frames. See bench_modes.cpp.
#include <cstdio>
#include <string_view>

#include "bench_modes.h"

int main(int argc, char** argv) {
    using namespace caustics::bench;
    auto options = parseBenchOptions(argc, argv);
    if (!options) {
        std::fprintf(stderr, "caustics-bench: %s\n%s", options.message().c_str(), benchUsage().c_str());
        return 2;
    }
    for (const BenchMode& mode : benchModes())
        if (options->mode == mode.name) return mode.run(options.value());
    std::fprintf(stderr, "caustics-bench: unknown mode '%s'\n%s", options->mode.c_str(), benchUsage().c_str());
    return 2;
}
