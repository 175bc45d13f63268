#pragma once
// Command line of caustics-bench (see benchUsage()). Every value is range-checked here with a message
// naming the flag and the limit, so no mode meets an absurd size (no uncaught exception, no
// std::bad_alloc after minutes).
#include <cstdint>
#include <string>

#include "caustics/caustics_settings.h"
#include "caustics/rhi/device.h"

namespace caustics::bench {

struct BenchOptions {
    std::string mode;
    uint32_t width = 1920;
    uint32_t height = 1080;
    uint32_t frames = 30;           // timed frames per measurement (the median is reported)
    uint32_t warmupFrames = 2;
    bool warmupGiven = false;       // --warmup given: else a filtered measurement warms up longer (bench_measure.h)
    uint32_t triangles = 1000000;   // rays mode
    rhi::Backend backend = rhi::Backend::Vulkan;
    bool validation = false;
    // caustics / frame / sweep modes (paper section 4 defaults).
    std::string scenes = "builtin,builtin:atrium";   // comma list (sweep: the first one)
    uint32_t extraLights = 0;       // caustic spot lights added around the specular objects
    float raysPerTexel = 1.0f;
    uint32_t maxDepth = 4;
    uint32_t mapResolution = 512;
    bool filter = false;            // the paper measured with the filter off
    bool filterSecondTypeApart = CausticsSettings{}.filterSecondTypeApart;
    bool secondTypeSplitLobes = true;     // CausticsSettings::secondTypeSplitLobes
    float sphereRadiusScale = CausticsSettings{}.sphereRadiusScale;
    bool viewAway = false;          // caustics / frame: the camera turned away from every caustic (--view away)
    bool mapOccluders = false;      // CausticsSettings::mapOccluders
    std::string outDir;             // sweep: where the CSV files go
    uint32_t referenceFrames = 16;  // sweep: frames of the converged reference (x 16 rays per texel)
    std::string sweeps = "lights,rays,depth,map,image";   // sweep: which parameters to vary
    uint32_t photons = 0;           // CausticsSettings::photonsPerFrame (0: per-texel emission)
    float timeTargetMs = 0.0f;      // CausticsSettings::causticTimeTargetMs (level mode default 1 ms)
};

// Limits (inclusive) beyond which a flag is refused.
inline constexpr uint32_t kMaxBenchImageSide = 16384;
inline constexpr uint32_t kMaxBenchTriangles = 1u << 26;   // 64 M: ~1.6 GB of mesh on the host
inline constexpr uint32_t kMaxBenchFrames = 100000;
inline constexpr uint32_t kMaxBenchExtraLights = 32;

Result<BenchOptions> parseBenchOptions(int argc, char** argv);
std::string benchUsage();

}  // namespace caustics::bench
