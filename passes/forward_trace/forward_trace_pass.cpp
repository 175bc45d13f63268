// caustics.forward (paper 3.2, Figure 4): one ray-generation launch per (emitting texel, sample) of
// every map layer, in one dispatch whose grid caustics.photonPlan laid out on the GPU
// (dispatchRaysIndirect; without it, a direct dispatch over forwardLaunchBound whose launches past the
// last layer's range idle). The body, passes/forward_trace/shaders/forward.h, emits, traces the specular
// chain, splats first-type caustics atomically and stores the diffuse hits; forward_pipeline.cpp builds
// its pipeline.
#include <algorithm>
#include <cmath>

#include "caustic_maps/caustic_internal.h"
#include "caustics/rhi/log.h"
#include "forward_trace/shaders/forward.h"
#include "module/pass_bindings.h"

namespace caustics {

void addForwardPass(rg::RenderGraph& graph, CausticFrame& f) {
    graph.addPass("caustics.forward", [&](rg::PassBuilder& b) {
        b.setStages(rhi::PipelineStages::RayTracing);
        const CausticsSettings& s = f.in->settings;
        f.camera = b.read(f.camera, rg::Access::ConstantBuffer);
        if (f.in->sceneTlas.valid()) b.read(f.in->sceneTlas);
        f.maps = b.read(f.maps, rg::Access::SampledRead);
        f.emitters = b.read(f.emitters, rg::Access::SampledRead);
        const bool indirect = f.res->device->capabilities().rayTracingIndirect;
        if (indirect) f.forwardArgs = b.read(f.forwardArgs, rg::Access::IndirectArgument);
        rg::RgTexture linearDepth = b.read(f.in->gbuffer.linearDepth, rg::Access::SampledRead);
        rg::RgTexture objectId = b.read(f.in->gbuffer.objectId, rg::Access::SampledRead);
        f.radiance1 = b.write(f.radiance1, rg::Access::StorageReadWrite);
        f.stats = b.write(f.stats, rg::Access::StorageReadWrite);
        f.layerPlans = b.write(f.layerPlans, rg::Access::StorageReadWrite);
        f.owners = b.read(f.owners, rg::Access::SampledRead);
        f.instanceMotionRows = b.read(f.instanceMotionRows, rg::Access::SampledRead);
        f.casterMotionWords = b.write(f.casterMotionWords, rg::Access::StorageReadWrite);
        // Only the second type's gather reads the hits: without it the pass stores none, into a
        // one-record buffer the binding needs (docs/caustics.md, "Memory"), and exports no hit buffer.
        // A launch stores at most one hit, so the launch bound caps the buffer (docs/caustics.md, "Memory").
        const bool storeHits = s.secondType;
        f.hitCapacity = storeHits ? uint32_t(std::min<uint64_t>(s.maxStoredHits, forwardLaunchBound(s, f.plan))) : 0u;
        const uint32_t maxStoredHits = f.hitCapacity;
        f.hits = b.write(b.createBuffer("caustics.hits", rhi::BufferDesc()
                                                             .setByteSize(uint64_t(std::max(maxStoredHits, 1u)) * sizeof(CausticHit))
                                                             .setUsage(rhi::BufferUsage::Storage | rhi::BufferUsage::CopySource)
                                                             .setDebugName("caustics.hits")),
                         rg::Access::StorageWrite);
        const uint32_t layers = uint32_t(f.plan.maps.size());
        const shader::ForwardParams push{s.mapResolution, layers, f.plan.instanceCount, s.maxSpecularDepth,
                                         f.in->frameIndex * 0x9E3779B9u + s.seed,
                                         (s.russianRoulette ? shader::kForwardRussianRoulette : 0u) |
                                             (f.casterMotion ? shader::kForwardCasterMotion : 0u),
                                         maxStoredHits, 0};
        const uint64_t directLaunches = forwardLaunchBound(s, f.plan);
        CausticFrame h = f;
        rhi::BindingSetHandle sceneSet = f.in->sceneBindings->set;
        return [=](rg::PassContext& ctx) {
            CausticResources::Impl& r = *h.res;
            rhi::BindingSetHandle set = r.makeSet(*ctx.device(), r.forwardLayout, "caustics.forward",
                PassBindingSet(forwardBindings(r), 1)
                    .buffer("camera", ctx.buffer(h.camera))
                    .buffer("maps", ctx.buffer(h.maps))
                    .buffer("emitters", ctx.buffer(h.emitters))
                    .texture("gLinearDepth", ctx.texture(linearDepth))
                    .texture("gObjectId", ctx.texture(objectId))
                    .buffer("radianceWords", ctx.buffer(h.radiance1))
                    .buffer("hits", ctx.buffer(h.hits))
                    .buffer("stats", ctx.buffer(h.stats))
                    .buffer("plans", ctx.buffer(h.layerPlans))
                    .buffer("owners", ctx.buffer(h.owners))
                    .buffer("instanceMotion", ctx.buffer(h.instanceMotionRows))
                    .buffer("casterMotion", ctx.buffer(h.casterMotionWords)));
            if (!set) return;
            bindSceneTrace(ctx.cmd(), r.forwardState, r.forwardTable, sceneSet, set, push);
            if (indirect) ctx.cmd().dispatchRaysIndirect(ctx.buffer(h.forwardArgs));
            else ctx.cmd().dispatchRays(uint32_t(directLaunches), 1, 1);
        };
    });
}

}  // namespace caustics
