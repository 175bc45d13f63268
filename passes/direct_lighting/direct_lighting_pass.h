#pragma once
// Pass 2: deferred direct lighting with ray-traced shadows (a ray-tracing state object:
// raygen per pixel reading the G-buffer, shadow rays with a miss shader; no ray queries). Output:
// RGBA16_FLOAT linear radiance (cd/m^2 when lights are in candela/lux).
#include "caustics/frame_context.h"
#include "caustics/gbuffer.h"
#include "caustics/render_graph/render_graph.h"

namespace caustics {

class DirectLightingPass {
public:
    static constexpr rhi::Format kOutputFormat = rhi::Format::RGBA16_FLOAT;

    static Result<DirectLightingPass> create(rhi::IDevice& device, const rhi::BindingLayoutHandle& sceneLayout,
                                             const rhi::BindingLayoutHandle& cameraLayout);
    rg::RgTexture addToGraph(rg::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer) const;

private:
    rhi::BindingLayoutHandle layout_;
    rhi::StateObjectHandle stateObject_;
    rhi::ShaderTableHandle shaderTable_;
};

}  // namespace caustics
