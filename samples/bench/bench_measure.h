#pragma once
// One benchmark measurement: a scene, settings, image size and view, run for warm-up + timed frames
// through CausticsModule; per-pass GPU medians, the caustic counters of the last frame and the
// caustic transients' memory. Shared by the caustics mode (printed) and the sweep mode (CSV).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "bench_frame.h"
#include "bench_options.h"
#include "bench_scene.h"
#include "caustics/caustics_settings.h"
#include "caustics/scene/gpu_scene.h"

namespace caustics::bench {

struct Measurement {
    std::vector<std::pair<std::string, double>> passMs;   // every pass that ran, in order: median ms
    double frameMs = 0.0;                   // sum of all passes
    double causticsMs = 0.0;                // sum of the caustics.* passes
    uint32_t maps = 0;                      // caustic maps planned (lights with caustics)
    uint64_t photons = 0;                   // forward photon paths launched
    uint64_t emitterTexels = 0;             // map texels that emit (specular 3x3 neighbourhood)
    uint64_t dispatchedTexels = 0;          // map texels the forward dispatch covers
    uint64_t segments = 0;                  // forward ray segments traced (traceRay calls)
    uint64_t specularPixels = 0;            // camera pixels on a specular surface (caustics.specularPixels)
    uint64_t backwardLaunches = 0;          // launches of caustics.backward (= specular pixels when indirect)
    uint64_t spheres = 0;                   // second-type spheres (specular camera pixels with a diffuse hit)
    uint64_t sphereCapacity = 0;            // instances the sphere TLAS was built over (caustics/sphere_capacity.h)
    uint64_t spheresDropped = 0;            // spheres past that capacity (0 unless the view changed fast)
    uint64_t storedHits = 0;                // forward diffuse hits kept
    uint64_t hitAttempts = 0;               // forward diffuse hits offered (> kept: overflow)
    uint64_t gatherPairs = 0;
    std::vector<TransientMemory> transients;
    std::vector<MemoryEntry> persistent;    // CausticsModule::memoryReport() after the last frame
    uint64_t transientHeapBytes = 0;
    std::vector<float> caustics;            // RGBA32F caustic radiance of the last frame (if asked)

    // Sum of the medians of the passes whose name starts with `prefix` (0 if none ran).
    double passTime(const std::string& prefix) const;
};

CausticsSettings benchSettings(const BenchOptions& options);

// A scene on the GPU with its CausticsModule; runs that change only settings or the image size reuse
// it (pipelines are built once), as a host engine changing a setting would.
struct BenchSession {
    scene::Scene scene;
    std::unique_ptr<scene::GpuScene> gpu;
    std::unique_ptr<CausticsModule> module;
    static Result<std::unique_ptr<BenchSession>> create(const rhi::DeviceHandle& device, scene::Scene scene,
                                                        const CausticsSettings& settings);
};

// Warm-up frames of a measurement: --warmup, or, with the filter on, enough for its steady state: the
// history cap, then the frames in flight after which the pool's tile counts come back (docs/caustics.md "Cost":
// a young history leaves more pixels dark, which the a-trous passes skip; 2 warm-up frames measured the
// built-in scene's filter at 1.32 ms on the H200 against 1.69 ms after 60).
uint32_t warmupFrames(const BenchOptions& options, const CausticsSettings& settings);

// Renders warmup + frames frames with `settings`; readCaustics keeps the last frame's image.
Result<Measurement> measure(const rhi::DeviceHandle& device, BenchSession& session, const CausticsSettings& settings,
                            uint32_t width, uint32_t height, BenchView view, const BenchOptions& options,
                            bool readCaustics);

// Converged caustic reference: `frames` frames of 16 rays per texel, unfiltered, averaged (>= 256
// rays per texel for frames >= 16).
Result<std::vector<float>> causticReference(const rhi::DeviceHandle& device, BenchSession& session,
                                            CausticsSettings settings, uint32_t width, uint32_t height, uint32_t frames);

// Relative L1 of the RGB channels: sum |image - reference| / sum |reference|.
double relativeL1(const std::vector<float>& image, const std::vector<float>& reference);

}  // namespace caustics::bench
