#include "caustics_output_pass.h"

#include <string>

#include "caustics/pass_shaders.h"
#include "caustics_output/caustics_output_bindings.h"
#include "caustics_output/shaders/caustics_output.h"
#include "module/pass_bindings.h"

namespace caustics {

namespace {
static_assert(sizeof(shader::CausticsOutputParams) == 8);
const shader_bindings::PassBindings& kBindings = shader_bindings::kCausticsOutputBindings;
}  // namespace

Result<CausticsOutputPass> CausticsOutputPass::create(rhi::IDevice& device) {
    CausticsOutputPass pass;
    CAUSTICS_TRY(pass.layout_, createPassBindingLayout(device, kBindings, 0, rhi::ShaderStage::Fragment));
    CAUSTICS_TRY(pass.vertex_, pass_shaders::shaderCode(device.backend(), "caustics_output/caustics_output.vert"));
    CAUSTICS_TRY(pass.fragment_, pass_shaders::shaderCode(device.backend(), "caustics_output/caustics_output.frag"));
    return pass;
}

Result<rhi::GraphicsPipelineHandle> CausticsOutputPass::pipeline(rhi::IDevice& device, rhi::Format format,
                                                                 OutputWrite write) {
    if (auto it = pipelines_.find({format, write}); it != pipelines_.end()) return it->second;
    rhi::GraphicsPipelineDesc desc;
    desc.vertexShader = {vertex_, "main", rhi::ShaderStage::Vertex};
    desc.fragmentShader = {fragment_, "main", rhi::ShaderStage::Fragment};
    desc.bindings.layouts = {layout_};
    desc.bindings.pushConstantBytes = sizeof(shader::CausticsOutputParams);
    desc.cullMode = rhi::CullMode::None;
    desc.colorFormats = {format};
    desc.depthTest = false;
    desc.depthWrite = false;
    desc.additiveBlend = write == OutputWrite::Add;
    desc.debugName = std::string("caustics.output (") + rhi::formatInfo(format).name + ", " + outputWriteName(write) + ")";
    CAUSTICS_TRY(rhi::GraphicsPipelineHandle p, device.createGraphicsPipeline(desc));
    pipelines_[{format, write}] = p;
    return p;
}

Result<rg::RgTexture> CausticsOutputPass::addToGraph(rg::RenderGraph& graph, rhi::IDevice& device,
                                                     const CausticsOutputParams& params) {
    const bool hasCaustics = params.caustics.valid();
    if (!hasCaustics && params.write == OutputWrite::Add) return rg::RgTexture{};   // nothing to add
    rhi::GraphicsPipelineHandle pipe;
    if (hasCaustics) {
        CAUSTICS_TRY(pipe, pipeline(device, params.format, params.write));
    }
    rg::RgTexture out;
    graph.addPass("caustics.output", [&](rg::PassBuilder& b) {
        b.setStages(rhi::PipelineStages::Raster);
        const rg::RgTexture c = hasCaustics ? b.read(params.caustics) : rg::RgTexture{};
        out = b.write(params.target, rg::Access::RenderTarget);
        const shader::CausticsOutputParams pc{params.scale, params.write == OutputWrite::Replace ? 1.0f : 0.0f};
        const rg::RgTexture o = out;
        const uint32_t w = params.width, h = params.height;
        const rhi::BindingLayoutHandle layout = layout_;
        return [=](rg::PassContext& ctx) {
            rhi::RenderingDesc rd;
            rd.width = w;
            rd.height = h;
            rhi::ColorAttachment a;
            a.texture = ctx.texture(o);
            a.clear = !hasCaustics;   // Replace without caustics (off, or no light): zero radiance
            a.clearValue[3] = 1.0f;
            rd.colors.push_back(a);
            rhi::ICommandList& cmd = ctx.cmd();
            cmd.beginRendering(rd);
            if (hasCaustics) {
                auto sd = PassBindingSet(kBindings, 0).texture("caustics", ctx.texture(c)).desc();
                auto set = sd ? ctx.device()->createBindingSet(*sd, layout)
                              : Result<rhi::BindingSetHandle>(makeError(sd.message()));
                if (!set) {
                    log(LogLevel::Error, "caustics.output: " + set.message());
                } else {
                    cmd.setGraphicsPipeline(pipe);
                    cmd.setViewport(0.0f, 0.0f, float(w), float(h));
                    cmd.setBindingSet(0, *set);
                    cmd.setPushConstants(&pc, sizeof(pc));
                    cmd.draw(3);
                }
            }
            cmd.endRendering();
        };
    });
    return out;
}

}  // namespace caustics
