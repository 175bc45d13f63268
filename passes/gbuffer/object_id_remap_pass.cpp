#include "object_id_remap_pass.h"

#include "caustic_filter/caustic_filter.h"   // makeBindingLayout, makeComputePipeline

namespace caustics {

namespace {
struct PushConstants {
    uint32_t width, height;
    uint32_t pairCount;
    uint32_t pad;
};
static_assert(sizeof(PushConstants) == 16);   // Params of remap_object_ids.comp (GLSL and HLSL)
}  // namespace

Result<ObjectIdRemapPass> ObjectIdRemapPass::create(rhi::IDevice& device) {
    ObjectIdRemapPass pass;
    CAUSTICS_TRY(pass.layout_, makeBindingLayout(device, {{0, rhi::BindingType::SampledTexture},
                                                          {1, rhi::BindingType::StorageBufferRO},
                                                          {2, rhi::BindingType::StorageTexture}}));
    CAUSTICS_TRY(pass.pipeline_, makeComputePipeline(device, "gbuffer/remap_object_ids.comp", pass.layout_,
                                                     sizeof(PushConstants)));
    return pass;
}

rg::RgTexture ObjectIdRemapPass::addToGraph(rg::RenderGraph& graph, rg::RgTexture hostIds, rg::RgBuffer map,
                                            uint32_t pairCount, uint32_t width, uint32_t height) const {
    rg::RgTexture out;
    graph.addPass("gbuffer.object_ids", [&](rg::PassBuilder& b) {
        rg::RgTexture ids = b.read(hostIds);
        rg::RgBuffer pairs = b.read(map, rg::Access::SampledRead);
        out = b.write(b.createTexture("module objectId",
                                      gbufferTextureDesc(GBufferFormats::kObjectId, width, height, "module objectId")),
                      rg::Access::StorageWrite);
        const PushConstants pc{width, height, pairCount, 0};
        rg::RgTexture written = out;
        rhi::BindingLayoutHandle layout = layout_;
        rhi::ComputePipelineHandle pipeline = pipeline_;
        return [=](rg::PassContext& ctx) {
            rhi::BindingSetDesc sd;
            sd.add(rhi::BindingSetItem::sampledTexture(0, ctx.texture(ids)))
                .add(rhi::BindingSetItem::storageBuffer(1, ctx.buffer(pairs), false))
                .add(rhi::BindingSetItem::storageTexture(2, ctx.texture(written)));
            auto set = ctx.device()->createBindingSet(sd, layout);
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
