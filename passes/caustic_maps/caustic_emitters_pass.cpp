// caustics.emitters: compacts the map texels that emit (specular 3x3 neighbourhood of an instance the
// layer owns, inside the spot cone) into one list segment per layer (layer x mapResolution^2) and counts
// them per layer, so that caustics.forward launches only where photons leave (the paper's "adjust the
// rays emitting PDF", 3.2; docs/caustics.md, "Cost"). The flux of a texel is unchanged: the same texels
// emit the same photons as a dispatch over the whole map.
#include "caustic_maps/caustic_internal.h"
#include "caustic_maps/emitters_bindings.h"
#include "caustic_maps/shaders/emitters.h"
#include "caustics/rhi/log.h"
#include "module/pass_bindings.h"

namespace caustics {

// The packed emitter (shaders/common/caustic_map.h) has 13 bits per coordinate and
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
        const shader::EmittersParams push{n, f.plan.instanceCount};
        CausticFrame h = f;
        rhi::BindingSetHandle sceneSet = f.in->sceneBindings->set;
        return [=](rg::PassContext& ctx) {
            CausticResources::Impl& r = *h.res;
            rhi::BindingSetHandle set = r.makeSet(*ctx.device(), r.emitterLayout, "caustics.emitters",
                PassBindingSet(shader_bindings::kEmittersBindings, 1)
                    .buffer("maps", ctx.buffer(h.maps))
                    .texture("mapObjectIds", ctx.texture(h.mapIds))
                    .buffer("emitters", ctx.buffer(h.emitters))
                    .buffer("plans", ctx.buffer(h.layerPlans))
                    .buffer("stats", ctx.buffer(h.stats))
                    .buffer("owners", ctx.buffer(h.owners)));
            if (!set) return;
            rhi::ICommandList& cmd = ctx.cmd();
            cmd.setComputePipeline(r.emitterPipeline);
            cmd.setBindingSet(0, sceneSet);
            cmd.setBindingSet(1, set);
            cmd.setPushConstants(&push, sizeof(push));
            cmd.dispatch((n + 7) / 8, (n + 7) / 8, layers);
        };
    });
}

}  // namespace caustics
