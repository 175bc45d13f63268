#include "bench_modes.h"

namespace caustics::bench {

std::span<const BenchMode> benchModes() {
    static const BenchMode kModes[] = {
        {"rays", "primary and incoherent rays against a procedural ~1M-triangle mesh", runRaysMode},
        {"caustics", "per-pass GPU times and counters of the caustic passes on the built-in scenes", runCausticsMode},
        {"frame", "per-pass GPU times of the whole CausticsModule frame on the built-in scenes", runFrameMode},
        {"sweep", "the paper's section-4 sweeps (lights, rays per texel, depth, map and image size) as CSV under --out",
         runSweepMode},
        {"memory", "the module's memory (persistent + peak transient) at 720p..4K, filter on and off; --out: memory.csv",
         runMemoryMode},
        {"figures", "the caustic images of Figures 10 and 12 (each rays per texel and depth) as PFM files under --out",
         runFiguresMode},
        {"level", "the game-level stand-in: object count, extent and photon budget sweeps, and 60 frames of a moving "
                  "camera under a GPU-time target, as CSV under --out",
         runLevelMode},
    };
    return kModes;
}

}  // namespace caustics::bench
