// A one-thread pass that turns a GPU counter of caustics.stats into the grid of an indirect ray
// dispatch (passes/caustic_maps/shaders/grid_from_count.h): the gather follows the stored-hit count
// and launches nothing when there is no sphere.
#include "caustic_maps/caustic_internal.h"
#include "caustic_maps/grid_from_count_bindings.h"
#include "caustic_maps/shaders/grid_from_count.h"
#include "caustics/rhi/log.h"
#include "module/pass_bindings.h"

namespace caustics {

rg::RgBuffer addGridFromCountPass(rg::RenderGraph& graph, CausticFrame& f, const char* name, uint32_t statSlot,
                                  uint32_t cap, uint32_t gateSlot) {
    rg::RgBuffer grid;
    graph.addPass(name, [&](rg::PassBuilder& b) {
        b.setStages(rhi::PipelineStages::Compute);
        f.stats = b.read(f.stats, rg::Access::SampledRead);
        grid = b.write(b.createBuffer(name, rhi::BufferDesc().setByteSize(12).setUsage(rhi::BufferUsage::Storage)
                                                .setDebugName(name)),
                       rg::Access::StorageWrite);
        CausticFrame h = f;
        rg::RgBuffer out = grid;
        return [=](rg::PassContext& ctx) {
            CausticResources::Impl& r = *h.res;
            rhi::BindingSetHandle set = r.makeSet(*ctx.device(), r.gridLayout, name,
                PassBindingSet(shader_bindings::kGridFromCountBindings, 0)
                    .buffer("counters", ctx.buffer(h.stats))
                    .buffer("grid", ctx.buffer(out)));
            if (!set) return;
            const shader::GridFromCountParams push{statSlot, cap, gateSlot};
            rhi::ICommandList& cmd = ctx.cmd();
            cmd.setComputePipeline(r.gridFromCount);
            cmd.setBindingSet(0, set);
            cmd.setPushConstants(&push, sizeof(push));
            cmd.dispatch(1, 1, 1);
        };
    });
    return grid;
}

}  // namespace caustics
