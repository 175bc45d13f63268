#pragma once
// Ray throughput of a TLAS through the RHI's ray-tracing path, with the benchmark's own raygen shaders
// (shaders/primary.rgen, shaders/incoherent.rgen): the `rays` mode measures it on a procedural mesh,
// the `sweep` mode on the swept scene's own TLAS (its incoherent ceiling, issue 11: the ceiling
// depends on the scene, so the forward pass is compared against the same scene in the same run).
#include <cstdint>
#include <string>
#include <vector>

#include "bench_options.h"
#include "caustics/rhi/rhi.h"

namespace caustics::bench {

// Mirrors `Frame` in shaders/rays_common.glsl.
struct RayFrameConstants {
    float cameraPosition[4], cameraRight[4], cameraUp[4], cameraForward[4];
    float boundsMin[4], boundsMax[4];   // incoherent rays start uniformly in this box
    uint32_t frame = 0;
    uint32_t pad[3] = {};
};

struct RayRate {
    std::string rayGen;        // "primary" or "incoherent"
    uint64_t raysPerFrame = 0;
    double medianMs = 0.0;
    double hitFraction = 0.0;  // rays that hit something: a check that they really reach the geometry
    double megaRaysPerSecond() const { return medianMs > 0.0 ? double(raysPerFrame) / (medianMs * 1e3) : 0.0; }
};

// Dispatches width x height rays of each named raygen against `tlas` for warm-up + timed frames
// (options.warmupFrames, options.frames) and returns the median GPU time per raygen.
Result<std::vector<RayRate>> measureRayRates(rhi::IDevice& device, const rhi::AccelStructHandle& tlas,
                                             RayFrameConstants constants, uint32_t width, uint32_t height,
                                             const BenchOptions& options, const std::vector<std::string>& rayGens);

}  // namespace caustics::bench
