#pragma once
// The caustics-only output (docs/embedding.md "Output target"): caustic radiance x scale drawn into
// the host's target as a colour attachment, Replace (no blending) or Add (ONE + ONE). Raster, compute
// would need storage images of the host's format (no BGRA8 or sRGB) and format-less reads for Add.
#include <map>
#include <utility>

#include "caustics/output_target.h"
#include "caustics/render_graph/render_graph.h"
#include "caustics/rhi/device.h"

namespace caustics {

struct CausticsOutputParams {
    rg::RgTexture caustics;   // RGBA32_FLOAT radiance; invalid: none (Replace clears, Add adds nothing)
    rg::RgTexture target;     // the imported host target, checked by checkCausticsOutputTarget
    rhi::Format format = rhi::Format::Unknown;
    uint32_t width = 0, height = 0;
    OutputWrite write = OutputWrite::Add;
    float scale = 1.0f;
};

class CausticsOutputPass {
public:
    static Result<CausticsOutputPass> create(rhi::IDevice& device);
    // The pipeline of one (format, write): made on first use, then kept for the module's life.
    Result<rhi::GraphicsPipelineHandle> pipeline(rhi::IDevice& device, rhi::Format format, OutputWrite write);
    // Declares pass "caustics.output"; returns the target's new version (invalid when no pass was needed).
    Result<rg::RgTexture> addToGraph(rg::RenderGraph& graph, rhi::IDevice& device, const CausticsOutputParams& params);

private:
    rhi::BindingLayoutHandle layout_;
    rhi::ShaderCode vertex_, fragment_;
    std::map<std::pair<rhi::Format, OutputWrite>, rhi::GraphicsPipelineHandle> pipelines_;
};

}  // namespace caustics
