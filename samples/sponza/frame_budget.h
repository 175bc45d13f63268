#pragma once
// Checks an image size against the device before the frame's resources are allocated, so that
// `--width 16384 --height 16384` is refused with the limit named instead of failing deep in an
// allocation. The memory a frame needs is measured from the module's own render graph, not guessed.
#include <cstdint>
#include <string>

#include "caustics/caustics_module.h"
#include "caustics/rhi/device.h"

namespace caustics::sample {

// The texture side and the largest single allocation (the sample's HDR read-back): no module needed.
Status checkFrameSize(const rhi::Capabilities& caps, uint32_t width, uint32_t height);

// The module's frame graph's transient heap as a function of its pixel count (a fit), for the module's
// current settings: what grows with the image and what does not, to explain a refusal.
struct FrameMemory {
    uint64_t fixedBytes = 0;          // transient heap at zero pixels: caustic maps, hit buffer, ...
    double heapBytesPerPixel = 0.0;   // transient heap growth per pixel: G-buffer, direct, caustic images, ...
    std::string largestFixed;         // the largest transient whose size does not depend on the pixels
    uint64_t largestFixedBytes = 0;   // (the hit buffer: CausticsSettings::maxStoredHits x 64 bytes)
};

// Per frame size, from the device's memory requirements of the persistent and read-back resources.
uint64_t persistentFrameBytes(rhi::IDevice& device, uint32_t width, uint32_t height, const CausticsSettings& s);

// The transient heap of the module's frame graph at width x height: the graph built and compiled
// against the device's memory requirements (each resource created unbound, never executed). Exact on
// any device, where a fit from small sizes is not (docs/viewer.md "Device limits"). An error names a
// resource the device cannot create.
Result<uint64_t> frameHeapBytes(rhi::IDevice& device, CausticsModule& module, uint32_t width, uint32_t height,
                                uint32_t nextFrameIndex = 0);

// Builds the module's frame graph at two small sizes (built and compiled against the device's memory
// requirements, never executed: the module commits nothing) and fits the transient heap's size, which
// the graph's aliasing makes linear in the pixel count (docs/viewer.md "Device limits").
Result<FrameMemory> measureFrameMemory(rhi::IDevice& device, CausticsModule& module);

// What the module holds for one frame at width x height (docs/caustics.md "Memory"): its memory report
// after building and compiling its frame graph at that size (never executed), with the graph's
// transients and "peak in one frame" line (appendFrameMemory). For the `frame memory` line, after
// checkFrameFitsDevice said the frame fits.
Result<std::vector<MemoryEntry>> moduleFrameReport(rhi::IDevice& device, CausticsModule& module, uint32_t width,
                                                   uint32_t height);

// checkFrameSize, then the frame's graph at this very size (frameHeapBytes): the transient heap (one
// allocation) against the largest allocation, and the whole frame against the device-local heap, both
// against `limits` (the device's own capabilities when null). Errors name the size, the limit and, for
// the heap, its largest fixed part (measureFrameMemory). `nextFrameIndex`: the frame the host renders
// next; the sizing graph is built for it, so that frame's own build undoes it (a graph built and dropped
// changes nothing only when the next build is for the same or an earlier frame, docs/embedding.md).
Status checkFrameFitsDevice(rhi::IDevice& device, CausticsModule& module, uint32_t width, uint32_t height,
                            uint32_t nextFrameIndex = 0, const rhi::Capabilities* limits = nullptr);

}  // namespace caustics::sample
