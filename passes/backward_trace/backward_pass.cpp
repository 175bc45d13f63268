// Second type (paper 3.3): caustics.specularPixels (specular_pixels_pass.cpp), caustics.backward
// (specular pixels -> spheres + their AABBs appended at a counter), caustics.sphereBlas (one AABB per
// sphere slot, the unwritten ones inactive; caustics/sphere_capacity.h), caustics.spheres (a top level
// of that one BLAS),
// caustics.gather (stored forward hits x spheres, any-hit density estimate) and caustics.sphereCount.
// The cost follows the specular pixels and stored hits, not W x H (docs/caustics.md, "Second-type cost").
#include <algorithm>

#include "backward_trace/backward_bindings.h"
#include "backward_trace/gather_bindings.h"
#include "backward_trace/shaders/backward.h"
#include "backward_trace/shaders/gather.h"
#include "caustic_maps/caustic_internal.h"
#include "module/pass_bindings.h"

namespace caustics {

void addBackwardPasses(rg::RenderGraph& graph, CausticFrame& f) {
    CausticResources::Impl& res = *f.res;
    const bool indirect = res.device->capabilities().rayTracingIndirect;
    prepareSphereBudget(f);
    addSpecularPixelPass(graph, f);
    graph.addPass("caustics.backward", [&](rg::PassBuilder& b) {
        b.setStages(rhi::PipelineStages::RayTracing);
        const CausticsSettings& s = f.in->settings;
        f.camera = b.read(f.camera, rg::Access::ConstantBuffer);
        if (f.in->sceneTlas.valid()) b.read(f.in->sceneTlas);
        f.specularPixels = b.read(f.specularPixels, rg::Access::SampledRead);
        if (indirect) f.backwardArgs = b.read(f.backwardArgs, rg::Access::IndirectArgument);
        f.spheres = b.write(b.createBuffer("caustics.spheres", rhi::BufferDesc().setByteSize(uint64_t(f.sphereAllocation) * sizeof(CausticSphere))
                                                                   .setUsage(rhi::BufferUsage::Storage).setDebugName("caustics.spheres")),
                            rg::Access::StorageWrite);
        f.sphereAabbs = b.write(f.sphereAabbs, rg::Access::StorageWrite);
        f.stats = b.write(f.stats, rg::Access::StorageReadWrite);
        shader::BackwardParams push{s.sphereRadiusPolicy == SphereRadiusPolicy::PixelFootprint ? shader::kBackwardRadiusFootprint
                                                                                              : shader::kBackwardRadiusWorld,
                                    s.sphereRadiusScale,
                                    s.sphereWorldRadius,
                                    s.maxSpecularDepth,
                                    f.in->frameIndex * 0x9E3779B9u + s.seed,
                                    s.sphereMinMagnification,
                                    s.sphereMaxMagnification,
                                    s.sphereMinRadius,
                                    s.sphereMaxRadius,
                                    0,    // sphereCapacity: set when the graph executes
                                    s.secondTypeSplitLobes ? shader::kBackwardMaxSpheres : 1u,
                                    0};
        CausticFrame h = f;
        rhi::BindingSetHandle sceneSet = f.in->sceneBindings->set;
        return [=](rg::PassContext& ctx) mutable {
            CausticResources::Impl& r = *h.res;
            rhi::BindingSetHandle set = r.makeSet(*ctx.device(), r.backwardLayout, "caustics.backward",
                PassBindingSet(shader_bindings::kBackwardBindings, 1)
                    .buffer("camera", ctx.buffer(h.camera))
                    .buffer("spheres", ctx.buffer(h.spheres))
                    .buffer("sphereAabbs", ctx.buffer(h.sphereAabbs))
                    .buffer("stats", ctx.buffer(h.stats))
                    .buffer("specularPixels", ctx.buffer(h.specularPixels)));
            if (!set) return;
            push.sphereCapacity = *h.sphereCapacity;
            bindSceneTrace(ctx.cmd(), r.backwardState, r.backwardTable, sceneSet, set, push);
            // Without indirect dispatch: one launch per pixel; launches past the list's length idle.
            if (indirect) ctx.cmd().dispatchRaysIndirect(ctx.buffer(h.backwardArgs));
            else ctx.cmd().dispatchRays(h.width * h.height, 1, 1);
        };
    });

    f.sphereBlas = graph.importAccelStruct("caustics.sphereBlas", res.sphereBlas, rhi::ResourceState::AccelStructRead,
                                           rhi::ResourceState::AccelStructRead);
    f.sphereTlas = graph.importAccelStruct("caustics.sphereTlas", res.sphereTlas, rhi::ResourceState::AccelStructRead,
                                           rhi::ResourceState::AccelStructRead);
    graph.addPass("caustics.sphereBlas", [&](rg::PassBuilder& b) {
        f.sphereAabbs = b.read(f.sphereAabbs, rg::Access::AccelStructBuildInput);
        f.sphereBlas = b.write(f.sphereBlas, rg::Access::AccelStructBuild);
        CausticFrame h = f;
        return [=](rg::PassContext& ctx) {
            if (*h.sphereCapacity == 0) return;   // no sphere the earlier frame: nothing built, nothing gathered
            ctx.cmd().buildBottomLevel(ctx.accelStruct(h.sphereBlas));
        };
    });
    graph.addPass("caustics.spheres", [&](rg::PassBuilder& b) {
        f.sphereBlas = b.read(f.sphereBlas, rg::Access::AccelStructBuildRead);
        f.sphereTlas = b.write(f.sphereTlas, rg::Access::AccelStructBuild);
        CausticFrame h = f;
        return [=](rg::PassContext& ctx) {
            if (*h.sphereCapacity == 0) return;
            // Identity transform; the intersection shader reads each sphere by its primitive index.
            rhi::InstanceDesc one;
            one.blasAddress = ctx.accelStruct(h.sphereBlas)->deviceAddress();
            ctx.cmd().buildTopLevel(ctx.accelStruct(h.sphereTlas), std::span<const rhi::InstanceDesc>(&one, 1));
        };
    });

    // The gather's grid is the stored-hit count (clamped to the buffer), counted on the GPU; no launch
    // at all when no pixel has a sphere (camera turned away from every specular object).
    rg::RgBuffer gatherGrid;
    if (indirect)
        gatherGrid = addGridFromCountPass(graph, f, "caustics.gatherGrid", kStatStoredHitAttempts,
                                          f.hitCapacity, kStatSpheres);
    graph.addPass("caustics.gather", [&](rg::PassBuilder& b) {
        b.setStages(rhi::PipelineStages::RayTracing);
        if (indirect) gatherGrid = b.read(gatherGrid, rg::Access::IndirectArgument);
        f.sphereTlas = b.read(f.sphereTlas, rg::Access::AccelStructTrace);
        f.spheres = b.read(f.spheres, rg::Access::SampledRead);
        f.hits = b.read(f.hits, rg::Access::SampledRead);
        f.stats = b.write(f.stats, rg::Access::StorageReadWrite);
        f.secondTypeTarget() = b.write(f.secondTypeTarget(), rg::Access::StorageReadWrite);
        f.specularIndex = b.read(f.specularIndex, rg::Access::SampledRead);
        uint32_t maxHits = f.hitCapacity;
        CausticFrame h = f;
        return [=](rg::PassContext& ctx) {
            if (*h.sphereCapacity == 0) return;   // the TLAS was not built this frame
            CausticResources::Impl& r = *h.res;
            rhi::BindingSetHandle set = r.makeSet(*ctx.device(), r.gatherLayout, "caustics.gather",
                PassBindingSet(gatherBindings(r), 0)
                    .accelStruct("sphereTlas", ctx.accelStruct(h.sphereTlas))
                    .buffer("spheres", ctx.buffer(h.spheres))
                    .buffer("hits", ctx.buffer(h.hits))
                    .buffer("stats", ctx.buffer(h.stats))
                    .buffer("radianceWords", ctx.buffer(h.secondTypeTarget()))
                    .texture("specularIndex", ctx.texture(h.specularIndex)));
            if (!set) return;
            rhi::ICommandList& cmd = ctx.cmd();
            cmd.setRayTracingState(r.gatherState, r.gatherTable);
            cmd.setBindingSet(0, set);
            const shader::GatherParams push{maxHits, h.width, h.secondTypeListOrder ? 1u : 0u};
            cmd.setPushConstants(&push, sizeof(push));
            // Without indirect dispatch: launched for the buffer's capacity; launches past the stored
            // count return at once.
            if (indirect) cmd.dispatchRaysIndirect(ctx.buffer(gatherGrid));
            else cmd.dispatchRays(maxHits, 1, 1);
        };
    });
    addSphereCountReadbackPass(graph, f);
}

}  // namespace caustics
