// A one-thread pass that turns a GPU counter of caustics.stats into the grid of an indirect ray
// dispatch (shaders/*/caustic_maps/grid_from_count.*): the gather follows the stored-hit count and
// launches nothing when there is no sphere.
#include "caustic_maps/caustic_internal.h"

namespace caustics {

rg::RgBuffer addGridFromCountPass(rg::RenderGraph& graph, CausticFrame& f, const char* name, uint32_t statSlot,
                                  uint32_t cap, uint32_t gateSlot) {
    rg::RgBuffer grid;
    graph.addPass(name, [&](rg::PassBuilder& b) {
        f.stats = b.read(f.stats, rg::Access::SampledRead);
        grid = b.write(b.createBuffer(name, rhi::BufferDesc().setByteSize(12).setUsage(rhi::BufferUsage::Storage)
                                                .setDebugName(name)),
                       rg::Access::StorageWrite);
        CausticFrame h = f;
        rg::RgBuffer out = grid;
        return [=](rg::PassContext& ctx) {
            CausticResources::Impl& r = *h.res;
            rhi::BindingSetHandle set = r.makeSet(*ctx.device(), r.gridLayout,
                                                  rhi::BindingSetDesc()
                                                      .add(rhi::BindingSetItem::storageBuffer(0, ctx.buffer(h.stats), false))
                                                      .add(rhi::BindingSetItem::storageBuffer(1, ctx.buffer(out))));
            if (!set) return;
            const uint32_t push[3] = {statSlot, cap, gateSlot};
            rhi::ICommandList& cmd = ctx.cmd();
            cmd.setComputePipeline(r.gridFromCount);
            cmd.setBindingSet(0, set);
            cmd.setPushConstants(push, sizeof(push));
            cmd.dispatch(1, 1, 1);
        };
    });
    return grid;
}

}  // namespace caustics
