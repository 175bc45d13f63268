#pragma once
// One CausticsModule frame as the benchmark runs it, through the public API only: adds the module's
// passes to a render graph, runs it, waits, and reads back the caustic statistics (caustic_passes.h)
// and, on request, the caustic radiance image. Per-pass GPU medians come from graph().
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "caustics/caustics_module.h"
#include "caustics/render_graph/render_graph.h"
#include "caustics/rhi/device.h"

namespace caustics::bench {

// A transient of the last frame and its size (render-graph heap placement may alias it with others).
struct TransientMemory {
    std::string name;
    uint64_t bytes = 0;
};

class BenchFrames {
public:
    static Result<std::unique_ptr<BenchFrames>> create(rhi::DeviceHandle device, CausticsModule& module,
                                                       uint32_t width, uint32_t height);
    // Renders one frame and waits for it; readCaustics copies the caustic radiance (RGBA32F) back.
    Status render(const scene::Camera& camera, uint32_t frameIndex, bool readCaustics);

    const std::vector<uint32_t>& stats() const { return stats_; }   // kStatCount words of the last frame
    const std::vector<float>& caustics() const { return caustics_; }   // RGBA per pixel, row 0 = top
    std::vector<TransientMemory> transients() const;   // caustics.* transients of the last frame
    uint64_t transientHeapBytes() const;                // the graph's heap (after aliasing)
    rg::RenderGraph& graph() { return graph_; }
    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }

private:
    BenchFrames() = default;
    rhi::DeviceHandle device_;
    CausticsModule* module_ = nullptr;
    uint32_t width_ = 0, height_ = 0;
    rg::RenderGraph graph_;
    rhi::CommandListHandle cmd_;
    rhi::BufferHandle statsReadback_, causticsReadback_;
    std::vector<uint32_t> stats_;
    std::vector<float> caustics_;
};

}  // namespace caustics::bench
