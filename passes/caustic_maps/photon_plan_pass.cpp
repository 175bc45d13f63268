// caustics.photonPlan: one thread turns the per-layer emitter counts of caustics.emitters and each
// layer's photon budget (CausticMapGpu::photons, planned on the CPU from the view coverage) into
// photons per texel, launch ranges and the forward pass's grid (passes/caustic_maps/shaders/
// photon_plan.h; docs/caustics.md, "Photon budget"). The split needs the emitter counts, which only the
// GPU knows this frame, so nothing is read back.
#include <cstddef>

#include "caustic_maps/caustic_internal.h"
#include "caustic_maps/photon_plan_bindings.h"
#include "caustic_maps/shaders/photon_plan.h"
#include "caustics/rhi/log.h"
#include "module/pass_bindings.h"

namespace caustics {
namespace {
// The shader's view of the C++ structs (common/layer_plan.h, photon_plan.h).
using shader::CausticLayerPlan;
static_assert(sizeof(CausticLayerPlan) == sizeof(CausticLayerPlanGpu) &&
              offsetof(CausticLayerPlan, emitters) == offsetof(CausticLayerPlanGpu, emitters) &&
              offsetof(CausticLayerPlan, raysPerTexel) == offsetof(CausticLayerPlanGpu, raysPerTexel) &&
              offsetof(CausticLayerPlan, samplesPerTexel) == offsetof(CausticLayerPlanGpu, samplesPerTexel) &&
              offsetof(CausticLayerPlan, launchOffset) == offsetof(CausticLayerPlanGpu, launchOffset) &&
              offsetof(CausticLayerPlan, launches) == offsetof(CausticLayerPlanGpu, launches) &&
              offsetof(CausticLayerPlan, emitted) == offsetof(CausticLayerPlanGpu, emitted));
static_assert(sizeof(CausticMapGpu) == 4 * shader::kCausticMapWords &&
              offsetof(CausticMapGpu, photons) == 4 * shader::kCausticMapPhotonsWord);
}  // namespace

void addPhotonPlanPass(rg::RenderGraph& graph, CausticFrame& f) {
    graph.addPass("caustics.photonPlan", [&](rg::PassBuilder& b) {
        b.setStages(rhi::PipelineStages::Compute);
        f.maps = b.read(f.maps, rg::Access::SampledRead);
        f.layerPlans = b.write(f.layerPlans, rg::Access::StorageReadWrite);
        f.forwardArgs = b.write(f.forwardArgs, rg::Access::StorageWrite);
        const shader::PhotonPlanParams push{uint32_t(f.plan.maps.size()), f.in->settings.raysPerTexel};
        CausticFrame h = f;
        return [=](rg::PassContext& ctx) {
            CausticResources::Impl& r = *h.res;
            rhi::BindingSetHandle set = r.makeSet(*ctx.device(), r.photonPlanLayout, "caustics.photonPlan",
                PassBindingSet(shader_bindings::kPhotonPlanBindings, 0)
                    .buffer("mapWords", ctx.buffer(h.maps))
                    .buffer("plans", ctx.buffer(h.layerPlans))
                    .buffer("args", ctx.buffer(h.forwardArgs)));
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
