#pragma once
// Command line of caustics-bench: `caustics-bench <mode> [--width W --height H --frames N
// --triangles T --backend vulkan|d3d12 --validation]`.
#include <cstdint>
#include <string>

#include "caustics/rhi/device.h"

namespace caustics::bench {

struct BenchOptions {
    std::string mode;
    uint32_t width = 1920;
    uint32_t height = 1080;
    uint32_t frames = 30;           // timed frames per measurement (the median is reported)
    uint32_t warmupFrames = 2;
    uint32_t triangles = 1000000;
    rhi::Backend backend = rhi::Backend::Vulkan;
    bool validation = false;
};

Result<BenchOptions> parseBenchOptions(int argc, char** argv);
std::string benchUsage();

}  // namespace caustics::bench
