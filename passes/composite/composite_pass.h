#pragma once
// Pass 7: composite (direct + caustic radiance), exposure, ACES-fitted tone map
// (Narkowicz 2015), sRGB encode to RGBA8; AOV selection. Compute.
#include <optional>

#include "caustics/gbuffer.h"
#include "caustics/render_graph/render_graph.h"
#include "caustics/rhi/device.h"

namespace caustics {

enum class CompositeAov : uint32_t { Final = 0, Direct = 1, Caustics = 2, Albedo = 3, Normal = 4, Depth = 5 };

struct CompositeOutputs {
    rg::RgTexture display;   // RGBA8_UNORM, sRGB-encoded, tone-mapped selected AOV
    rg::RgTexture hdr;       // RGBA32_FLOAT, the selected AOV in linear units, before exposure
};

struct CompositeParams {
    CompositeAov aov = CompositeAov::Final;
    float exposure = 1.0f;
    float depthRange = 20.0f;
    rg::RgTexture display;   // optional: write into this (an imported host target, RGBA8_UNORM)
};

class CompositePass {
public:
    static Result<CompositePass> create(rhi::IDevice& device);
    // caustics: invalid handle = no caustics (zero).
    CompositeOutputs addToGraph(rg::RenderGraph& graph, const GBuffer& gbuffer, rg::RgTexture direct,
                                rg::RgTexture caustics, const CompositeParams& params) const;

private:
    rhi::BindingLayoutHandle layout_;
    rhi::ComputePipelineHandle pipeline_;
};

}  // namespace caustics
