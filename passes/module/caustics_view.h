#pragma once
// One view's state across frames (CausticsView in caustics/caustics_module.h): camera buffers per
// frame-in-flight slot, the view-projection of its last EXECUTED frame and its filter history.
#include <optional>
#include <vector>

#include "caustics/camera_constants.h"
#include "caustics/caustic_passes.h"
#include "caustics/caustics_module.h"
#include "caustics/render_graph/render_graph.h"

namespace caustics {

struct CausticsView::Impl {
    std::vector<rhi::BufferHandle> cameraBuffers;      // host-visible CameraConstants, one per slot
    std::vector<rhi::BindingSetHandle> cameraSets;
    std::optional<glm::mat4> lastViewProj;             // of the last executed frame
    CausticViewHistory history;

    static Result<std::unique_ptr<Impl>> create(rhi::IDevice& device, const rhi::BindingLayoutHandle& cameraLayout,
                                                uint32_t framesInFlight);

    // The previous view-projection this frame reprojects from: the host's, else the last executed
    // frame's, else (first frame or a camera cut) none.
    std::optional<glm::mat4> previousViewProj(const CameraView& camera, bool cameraCut) const;

    // Adds "view.begin" (never culled, first in the graph): when the graph executes it writes `camera`
    // into slot `slot`'s buffer and records this frame's view-projection as the view's last one.
    void addBeginPass(rg::RenderGraph& graph, const CameraConstants& camera, uint32_t slot);
};

}  // namespace caustics
