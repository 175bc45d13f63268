#pragma once
// Headless frame loop of the sample: builds the render graph with CausticsModule each frame, runs it,
// and reads the display (RGBA8) and HDR (RGBA32F) images back to the host.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "caustics/caustics_module.h"
#include "caustics/render_graph/render_graph.h"
#include "caustics/rhi/device.h"

namespace caustics::sample {

struct FrameImages {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> display;   // RGBA8, sRGB-encoded
    std::vector<float> hdr;         // RGBA32F linear
};

class FrameRenderer {
public:
    static Result<std::unique_ptr<FrameRenderer>> create(rhi::DeviceHandle device, CausticsModule& module,
                                                         uint32_t width, uint32_t height);
    // Renders one frame and waits for it; readBack copies the images to the host.
    Status render(const scene::Camera& camera, uint32_t frameIndex, bool readBack);
    const FrameImages& images() const { return images_; }
    // The last frame's caustic statistics (uint32[kStatCount], caustic_passes.h); zeros when caustics are off.
    const std::vector<uint32_t>& stats() const { return stats_; }
    rg::RenderGraph& graph() { return graph_; }

private:
    FrameRenderer() = default;
    rhi::DeviceHandle device_;
    CausticsModule* module_ = nullptr;
    rg::RenderGraph graph_;
    rhi::CommandListHandle cmd_;
    rhi::BufferHandle displayReadback_, hdrReadback_, statsReadback_;
    bool warnedAboutStats_ = false;
    FrameImages images_;
    std::vector<uint32_t> stats_;
};

}  // namespace caustics::sample
