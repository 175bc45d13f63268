#pragma once
// The benchmark's modes. Adding one = one mode_<name>.cpp defining its run function plus one line in
// bench_modes.cpp.
#include <span>

#include "bench_options.h"

namespace caustics::bench {

struct BenchMode {
    const char* name;
    const char* summary;
    int (*run)(const BenchOptions& options);   // process exit code
};

std::span<const BenchMode> benchModes();

int runRaysMode(const BenchOptions& options);
int runCausticsMode(const BenchOptions& options);
int runFrameMode(const BenchOptions& options);
int runSweepMode(const BenchOptions& options);
int runFiguresMode(const BenchOptions& options);
int runLevelMode(const BenchOptions& options);
int runMemoryMode(const BenchOptions& options);

}  // namespace caustics::bench
