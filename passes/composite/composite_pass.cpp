#include "composite_pass.h"

#include "caustics/pass_shaders.h"

namespace caustics {

namespace {
struct PushConstants {
    uint32_t aov;
    uint32_t hasCaustics;
    float exposure;
    float depthRange;
    uint32_t width, height;
};
static_assert(sizeof(PushConstants) == 24);   // Params of composite.comp (GLSL and HLSL)
}  // namespace

Result<CompositePass> CompositePass::create(rhi::IDevice& device) {
    CompositePass pass;
    rhi::BindingLayoutDesc ld;
    ld.setVisibility(rhi::ShaderStage::Compute);
    for (uint32_t i = 0; i < 5; ++i) ld.add(i, rhi::BindingType::SampledTexture);
    ld.add(5, rhi::BindingType::StorageTexture).add(6, rhi::BindingType::StorageTexture);
    CAUSTICS_TRY(pass.layout_, device.createBindingLayout(ld));
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
                         gbuffer.width, gbuffer.height};
        CompositeOutputs o = out;
        rhi::BindingLayoutHandle layout = layout_;
        rhi::ComputePipelineHandle pipeline = pipeline_;
        return [=](rg::PassContext& ctx) {
            rhi::BindingSetDesc sd;
            sd.add(rhi::BindingSetItem::sampledTexture(0, ctx.texture(d)))
                .add(rhi::BindingSetItem::sampledTexture(1, ctx.texture(c)))
                .add(rhi::BindingSetItem::sampledTexture(2, ctx.texture(albedo)))
                .add(rhi::BindingSetItem::sampledTexture(3, ctx.texture(normal)))
                .add(rhi::BindingSetItem::sampledTexture(4, ctx.texture(depth)))
                .add(rhi::BindingSetItem::storageTexture(5, ctx.texture(o.display)))
                .add(rhi::BindingSetItem::storageTexture(6, ctx.texture(o.hdr)));
            auto set = ctx.device()->createBindingSet(sd, layout);
            if (!set) {
                log(LogLevel::Error, "composite: " + set.message());
                return;
            }
            ctx.cmd().setComputePipeline(pipeline);
            ctx.cmd().setBindingSet(0, *set);
            ctx.cmd().setPushConstants(&pc, sizeof(pc));
            ctx.cmd().dispatch((pc.width + 7) / 8, (pc.height + 7) / 8, 1);
        };
    });
    return out;
}

}  // namespace caustics
