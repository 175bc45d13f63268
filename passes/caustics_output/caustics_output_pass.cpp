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

std::string quoted(const rhi::TextureDesc& desc) { return desc.debugName.empty() ? "" : " '" + desc.debugName + "'"; }
}  // namespace

const char* outputWriteName(OutputWrite write) { return write == OutputWrite::Add ? "Add" : "Replace"; }

bool causticsOutputFormatSupported(rhi::Format format) {
    switch (format) {
        case rhi::Format::RGBA8_UNORM:
        case rhi::Format::RGBA8_SRGB:
        case rhi::Format::BGRA8_UNORM:
        case rhi::Format::RGBA16_FLOAT:
        case rhi::Format::RGBA32_FLOAT:
        case rhi::Format::R11G11B10_FLOAT:
        case rhi::Format::RGB10A2_UNORM: return true;
        default: return false;
    }
}

Status checkCausticsOutputTarget(const rhi::TextureDesc& desc, uint32_t width, uint32_t height, const char* field) {
    const std::string what = std::string("CausticsModule::addPasses: ") + field + quoted(desc) + " (" +
                             rhi::formatInfo(desc.format).name + ")";
    if (!causticsOutputFormatSupported(desc.format)) {
        const rhi::FormatInfo& info = rhi::formatInfo(desc.format);
        const char* why = info.isDepth     ? "a depth format"
                          : info.isInteger ? "an integer format (no blending, no colour conversion)"
                          : desc.format == rhi::Format::RGB32_FLOAT ? "a vertex format"
                                                                    : "fewer than three channels (green and blue would be dropped)";
        return makeError(what + " is " + why + ": caustics-only output needs a float or unorm colour format with "
                         "three or four channels: RGBA8_UNORM, RGBA8_SRGB, BGRA8_UNORM, RGB10A2_UNORM, RGBA16_FLOAT, "
                         "R11G11B10_FLOAT or RGBA32_FLOAT");
    }
    if (!rhi::hasAny(desc.usage, rhi::TextureUsage::RenderTarget))
        return makeError(what + " lacks RenderTarget usage: the caustics are drawn into it as a colour attachment");
    if (desc.dimension != rhi::TextureDimension::Texture2D || desc.arrayLayers != 1 || desc.mipLevels != 1)
        return makeError(what + " must be a 2D texture of one layer and one mip level (it has " +
                         std::to_string(desc.arrayLayers) + " layers, " + std::to_string(desc.mipLevels) + " mips)");
    if (desc.width != width || desc.height != height)
        return makeError(what + " is " + std::to_string(desc.width) + "x" + std::to_string(desc.height) +
                         ", the image (FrameInputs::width x height) is " + std::to_string(width) + "x" +
                         std::to_string(height));
    return okStatus();
}

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
