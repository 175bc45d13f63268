#pragma once
// Pass 1: the camera G-buffer by rasterization, one draw per scene instance with vertex
// pulling from the GPU scene buffers; writes the six targets of caustics/gbuffer.h.
#include "caustics/frame_context.h"
#include "caustics/gbuffer.h"
#include "caustics/render_graph/render_graph.h"

namespace caustics {

class GBufferPass {
public:
    static Result<GBufferPass> create(rhi::IDevice& device, const rhi::BindingLayoutHandle& sceneLayout,
                                      const rhi::BindingLayoutHandle& cameraLayout);
    GBuffer addToGraph(rg::RenderGraph& graph, const FrameContext& frame) const;

private:
    // Standard depth (clear 1, pass nearer = Less) and reversed depth (clear 0, Greater); the camera's
    // projection picks one each frame (CameraConstants::frame.w).
    rhi::GraphicsPipelineHandle pipeline_, reversedZPipeline_;
};

}  // namespace caustics
