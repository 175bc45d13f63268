#include "object_id_remap_pass.h"

#include "caustics/pass_shaders.h"
#include "gbuffer/remap_object_ids_bindings.h"
#include "gbuffer/shaders/remap_object_ids.h"
#include "module/pass_bindings.h"

namespace caustics {

namespace {
using PushConstants = shader::ObjectIdRemapParams;
static_assert(sizeof(PushConstants) == 16);
const shader_bindings::PassBindings& kBindings = shader_bindings::kRemapObjectIdsBindings;
}  // namespace

Result<ObjectIdRemapPass> ObjectIdRemapPass::create(rhi::IDevice& device) {
    ObjectIdRemapPass pass;
    CAUSTICS_TRY(pass.layout_, createPassBindingLayout(device, kBindings, 0, rhi::ShaderStage::All));
    rhi::ComputePipelineDesc desc;
    CAUSTICS_TRY(desc.shader.code, pass_shaders::shaderCode(device.backend(), "gbuffer/remap_object_ids.comp"));
    desc.shader.stage = rhi::ShaderStage::Compute;
    desc.bindings.layouts = {pass.layout_};
    desc.bindings.pushConstantBytes = sizeof(PushConstants);
    desc.debugName = "gbuffer/remap_object_ids.comp";
    CAUSTICS_TRY(pass.pipeline_, device.createComputePipeline(desc));
    return pass;
}

rg::RgTexture ObjectIdRemapPass::addToGraph(rg::RenderGraph& graph, rg::RgTexture hostIds, rg::RgBuffer map,
                                            uint32_t pairCount, uint32_t width, uint32_t height) const {
    rg::RgTexture out;
    graph.addPass("gbuffer.object_ids", [&](rg::PassBuilder& b) {
        b.setStages(rhi::PipelineStages::Compute);
        rg::RgTexture ids = b.read(hostIds);
        rg::RgBuffer pairs = b.read(map, rg::Access::SampledRead);
        out = b.write(b.createTexture("module objectId",
                                      gbufferTextureDesc(GBufferFormats::kObjectId, width, height, "module objectId")),
                      rg::Access::StorageWrite);
        const PushConstants pc{{width, height}, pairCount, 0};
        rg::RgTexture written = out;
        rhi::BindingLayoutHandle layout = layout_;
        rhi::ComputePipelineHandle pipeline = pipeline_;
        return [=](rg::PassContext& ctx) {
            auto sd = PassBindingSet(kBindings, 0)
                          .texture("hostObjectId", ctx.texture(ids))
                          .buffer("pairs", ctx.buffer(pairs))
                          .texture("moduleObjectId", ctx.texture(written))
                          .desc();
            auto set = sd ? ctx.device()->createBindingSet(*sd, layout) : Result<rhi::BindingSetHandle>(makeError(sd.message()));
            if (!set) {
                log(LogLevel::Error, "gbuffer.object_ids: " + set.message());
                return;
            }
            ctx.cmd().setComputePipeline(pipeline);
            ctx.cmd().setBindingSet(0, *set);
            ctx.cmd().setPushConstants(&pc, sizeof(pc));
            ctx.cmd().dispatch((width + 7) / 8, (height + 7) / 8, 1);
        };
    });
    return out;
}

}  // namespace caustics
