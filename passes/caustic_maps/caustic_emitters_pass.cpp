// caustics.emitters: compacts the map texels that emit (specular 3x3 neighbourhood of an instance the
// layer owns, inside the spot cone) into one list segment per layer (layer x mapResolution^2) and counts
// them per layer, so that caustics.forward launches only where photons leave (the paper's "adjust the
// rays emitting PDF", 3.2; docs/caustics.md, "Cost"). The flux of a texel is unchanged: the same texels
// emit the same photons as a dispatch over the whole map.
#include "caustic_maps/caustic_internal.h"

namespace caustics {

// The packed emitter (shaders/vulkan/caustic_maps/emitter_list.glsl) has 13 bits per coordinate and
// 6 bits of layer.
static_assert(CausticsSettings::kMaxMapResolution <= (1u << 13));
static_assert(kMaxCausticLights <= 64);

void addEmitterPass(rg::RenderGraph& graph, CausticFrame& f) {
    graph.addPass("caustics.emitters", [&](rg::PassBuilder& b) {
        b.setStages(rhi::PipelineStages::Compute);
        const uint32_t n = f.in->settings.mapResolution;
        const uint32_t layers = uint32_t(f.plan.maps.size());
        f.maps = b.read(f.maps, rg::Access::SampledRead);
        f.mapIds = b.read(f.mapIds, rg::Access::SampledRead);
        const uint64_t capacity = uint64_t(n) * n * layers;
        f.emitters = b.write(b.createBuffer("caustics.emitters", rhi::BufferDesc().setByteSize(capacity * 4)
                                                                     .setUsage(rhi::BufferUsage::Storage)
                                                                     .setDebugName("caustics.emitters")),
                             rg::Access::StorageWrite);
        f.layerPlans = b.write(f.layerPlans, rg::Access::StorageReadWrite);
        f.stats = b.write(f.stats, rg::Access::StorageReadWrite);
        f.owners = b.read(f.owners, rg::Access::SampledRead);
        const uint32_t push[2] = {n, f.plan.instanceCount};
        CausticFrame h = f;
        rhi::BindingSetHandle sceneSet = f.in->sceneBindings->set;
        return [=](rg::PassContext& ctx) {
            CausticResources::Impl& r = *h.res;
            rhi::BindingSetDesc d;
            d.add(rhi::BindingSetItem::storageBuffer(0, ctx.buffer(h.maps), false))
                .add(rhi::BindingSetItem::sampledTexture(1, ctx.texture(h.mapIds)))
                .add(rhi::BindingSetItem::storageBuffer(2, ctx.buffer(h.emitters)))
                .add(rhi::BindingSetItem::storageBuffer(3, ctx.buffer(h.layerPlans)))
                .add(rhi::BindingSetItem::storageBuffer(4, ctx.buffer(h.stats)))
                .add(rhi::BindingSetItem::storageBuffer(5, ctx.buffer(h.owners), false));
            rhi::BindingSetHandle set = r.makeSet(*ctx.device(), r.emitterLayout, d);
            if (!set) return;
            rhi::ICommandList& cmd = ctx.cmd();
            cmd.setComputePipeline(r.emitterPipeline);
            cmd.setBindingSet(0, sceneSet);
            cmd.setBindingSet(1, set);
            cmd.setPushConstants(push, sizeof(push));
            cmd.dispatch((n + 7) / 8, (n + 7) / 8, layers);
        };
    });
}

}  // namespace caustics
