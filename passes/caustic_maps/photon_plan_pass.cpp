// caustics.photonPlan: one thread turns the per-layer emitter counts of caustics.emitters and each
// layer's photon budget (CausticMapGpu::photons, planned on the CPU from the view coverage) into
// photons per texel, launch ranges and the forward pass's grid (shaders/*/caustic_maps/photon_plan.*;
// docs/caustics.md, "Photon budget"). The split needs the emitter counts, which only the GPU knows
// this frame, so nothing is read back.
#include "caustic_maps/caustic_internal.h"

namespace caustics {

void addPhotonPlanPass(rg::RenderGraph& graph, CausticFrame& f) {
    graph.addPass("caustics.photonPlan", [&](rg::PassBuilder& b) {
        f.maps = b.read(f.maps, rg::Access::SampledRead);
        f.layerPlans = b.write(f.layerPlans, rg::Access::StorageReadWrite);
        f.forwardArgs = b.write(f.forwardArgs, rg::Access::StorageWrite);
        struct Push {
            uint32_t layers;
            float raysPerTexel;
        } push{uint32_t(f.plan.maps.size()), f.in->settings.raysPerTexel};
        CausticFrame h = f;
        return [=](rg::PassContext& ctx) {
            CausticResources::Impl& r = *h.res;
            rhi::BindingSetHandle set = r.makeSet(*ctx.device(), r.photonPlanLayout,
                                                  rhi::BindingSetDesc()
                                                      .add(rhi::BindingSetItem::storageBuffer(0, ctx.buffer(h.maps), false))
                                                      .add(rhi::BindingSetItem::storageBuffer(1, ctx.buffer(h.layerPlans)))
                                                      .add(rhi::BindingSetItem::storageBuffer(2, ctx.buffer(h.forwardArgs))));
            if (!set) return;
            rhi::ICommandList& cmd = ctx.cmd();
            cmd.setComputePipeline(r.photonPlanPipeline);
            cmd.setBindingSet(0, set);
            cmd.setPushConstants(&push, sizeof(push));
            cmd.dispatch(1, 1, 1);
        };
    });
}

}  // namespace caustics
