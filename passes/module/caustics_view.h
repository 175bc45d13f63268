#pragma once
// One view's state across frames (CausticsView in caustics/caustics_module.h): camera buffers per
// frame-in-flight slot, the view-projection of its last EXECUTED frame and its filter history.
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "caustics/camera_constants.h"
#include "caustics/caustic_passes.h"
#include "caustics/caustics_module.h"
#include "caustics/render_graph/render_graph.h"

namespace caustics {

// Hands out view ids and collects those of destroyed views; the module releases their per-view state
// (CausticResources' sphere-count readbacks) at its next addPasses. Shared so that a view may outlive
// the module (it then has nobody to tell).
struct ViewRegistry {
    std::mutex mutex;
    uint64_t nextId = 1;
    std::vector<uint64_t> destroyed;
};

// What view.begin needs to complete a frame's previous view-projection when the graph executes.
struct BeginPassInputs {
    std::optional<glm::mat4> hostPrevViewProj;   // CameraView::prevViewProj
    bool unjitteredPrev = false;                 // CameraView::jitterPixels set: the host's is unjittered
    bool cameraCut = false;
    uint32_t frameIndex = 0;                     // FrameInputs::frameIndex
};

struct CausticsView::Impl {
    uint64_t id = 0;                                   // CausticViewHistory::viewId
    std::weak_ptr<ViewRegistry> registry;
    std::vector<rhi::BufferHandle> cameraBuffers;      // host-visible CameraConstants, one per slot
    std::vector<rhi::BindingSetHandle> cameraSets;
    std::optional<glm::mat4> lastViewProj;             // of the last executed frame (jittered)
    glm::vec2 lastJitterPixels{0.0f};                  // the jitter of the last executed frame
    std::optional<uint32_t> lastExecutedFrame;         // FrameInputs::frameIndex of the last executed frame
    CausticViewHistory history;

    static Result<std::unique_ptr<Impl>> create(rhi::IDevice& device, const rhi::BindingLayoutHandle& cameraLayout,
                                                uint32_t framesInFlight, const std::shared_ptr<ViewRegistry>& registry);
    ~Impl();

    // Adds "view.begin" (never culled, first in the graph): when the graph executes it completes
    // `camera`'s previous view-projection (the host's, jittered by the last executed frame's jitter when
    // it is unjittered; else this view's last executed frame's; none after a cut or on the first
    // frame), writes it into slot `slot`'s buffer and into the returned
    // constants (what the caustic passes upload), and records this frame's view-projection as the view's
    // last one. Resolving the previous frame then, not when the graph is built, is what lets a host build
    // frame n + 1 before it executes frame n. A frame number below the last executed one (without a cut)
    // is an execution error: frameIndex seeds the photons, and a slot index there repeats them.
    std::shared_ptr<const CameraConstants> addBeginPass(rg::RenderGraph& graph, const CameraConstants& camera,
                                                        uint32_t slot, const BeginPassInputs& inputs);
};

}  // namespace caustics
