#include "composite_pass.h"

#include "caustics/pass_shaders.h"
#include "composite/composite_bindings.h"
#include "composite/shaders/composite.h"
#include "module/pass_bindings.h"

namespace caustics {

namespace {
using PushConstants = shader::CompositeParams;
static_assert(sizeof(PushConstants) == 24);
static_assert(uint32_t(CompositeAov::Final) == shader::kAovFinal && uint32_t(CompositeAov::Direct) == shader::kAovDirect &&
              uint32_t(CompositeAov::Caustics) == shader::kAovCaustics && uint32_t(CompositeAov::Albedo) == shader::kAovAlbedo &&
              uint32_t(CompositeAov::Normal) == shader::kAovNormal && uint32_t(CompositeAov::Depth) == shader::kAovDepth);
const shader_bindings::PassBindings& kBindings = shader_bindings::kCompositeBindings;
}  // namespace

Result<CompositePass> CompositePass::create(rhi::IDevice& device) {
    CompositePass pass;
    CAUSTICS_TRY(pass.layout_, createPassBindingLayout(device, kBindings, 0, rhi::ShaderStage::Compute));
    rhi::ComputePipelineDesc desc;
    CAUSTICS_TRY(desc.shader.code, pass_shaders::shaderCode(device.backend(), "composite/composite.comp"));
    desc.shader.stage = rhi::ShaderStage::Compute;
    desc.bindings.layouts = {pass.layout_};
    desc.bindings.pushConstantBytes = sizeof(PushConstants);
    desc.debugName = "composite";
    CAUSTICS_TRY(pass.pipeline_, device.createComputePipeline(desc));
    return pass;
}

CompositeOutputs CompositePass::addToGraph(rg::RenderGraph& graph, const GBuffer& gbuffer, rg::RgTexture direct,
                                           rg::RgTexture caustics, const CompositeParams& params) const {
    CompositeOutputs out;
    graph.addPass("composite", [&](rg::PassBuilder& b) {
        b.setStages(rhi::PipelineStages::Compute);
        rg::RgTexture d = b.read(direct);
        bool hasCaustics = caustics.valid();
        rg::RgTexture c = hasCaustics ? b.read(caustics) : d;
        rg::RgTexture albedo = b.read(gbuffer.albedoMetallic);
        rg::RgTexture normal = b.read(gbuffer.normalRoughness);
        rg::RgTexture depth = b.read(gbuffer.linearDepth);
        rg::RgTexture display = params.display.valid()
                                    ? params.display
                                    : b.createTexture("display", gbufferTextureDesc(rhi::Format::RGBA8_UNORM, gbuffer.width,
                                                                                    gbuffer.height, "display"));
        out.display = b.write(display, rg::Access::StorageWrite);
        out.hdr = b.write(b.createTexture("hdr", gbufferTextureDesc(rhi::Format::RGBA32_FLOAT, gbuffer.width,
                                                                    gbuffer.height, "hdr")),
                          rg::Access::StorageWrite);
        PushConstants pc{uint32_t(params.aov), hasCaustics ? 1u : 0u, params.exposure, params.depthRange,
                         {gbuffer.width, gbuffer.height}};
        CompositeOutputs o = out;
        rhi::BindingLayoutHandle layout = layout_;
        rhi::ComputePipelineHandle pipeline = pipeline_;
        return [=](rg::PassContext& ctx) {
            auto sd = PassBindingSet(kBindings, 0)
                          .texture("direct", ctx.texture(d))
                          .texture("caustics", ctx.texture(c))
                          .texture("albedoMetallic", ctx.texture(albedo))
                          .texture("normalRoughness", ctx.texture(normal))
                          .texture("linearDepth", ctx.texture(depth))
                          .texture("display", ctx.texture(o.display))
                          .texture("hdr", ctx.texture(o.hdr))
                          .desc();
            auto set = sd ? ctx.device()->createBindingSet(*sd, layout) : Result<rhi::BindingSetHandle>(makeError(sd.message()));
            if (!set) {
                log(LogLevel::Error, "composite: " + set.message());
                return;
            }
            ctx.cmd().setComputePipeline(pipeline);
            ctx.cmd().setBindingSet(0, *set);
            ctx.cmd().setPushConstants(&pc, sizeof(pc));
            ctx.cmd().dispatch((pc.size.x + 7) / 8, (pc.size.y + 7) / 8, 1);
        };
    });
    return out;
}

}  // namespace caustics
