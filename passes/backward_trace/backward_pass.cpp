// Second type (paper 3.3): caustics.backward (camera specular pixels -> spheres + TLAS instances),
// caustics.spheres (TLAS over one unit-sphere BLAS, instances from the GPU buffer) and
// caustics.gather (stored forward hits x spheres, any-hit density estimate).
#include <cstring>

#include "caustic_maps/caustic_internal.h"

namespace caustics {

void addBackwardPasses(rg::RenderGraph& graph, CausticFrame& f) {
    CausticResources::Impl& res = *f.res;
    const uint32_t pixels = f.width * f.height;
    graph.addPass("caustics.backward", [&](rg::PassBuilder& b) {
        const CausticsSettings& s = f.in->settings;
        f.camera = b.read(f.camera, rg::Access::ConstantBuffer);
        if (f.in->sceneTlas.valid()) b.read(f.in->sceneTlas);
        rg::RgTexture objectId = b.read(f.in->gbuffer.objectId, rg::Access::SampledRead);
        rg::RgTexture optics = b.read(f.in->gbuffer.optics, rg::Access::SampledRead);
        f.spheres = b.write(b.createBuffer("caustics.spheres", rhi::BufferDesc().setByteSize(uint64_t(pixels) * sizeof(CausticSphere))
                                                                   .setUsage(rhi::BufferUsage::Storage).setDebugName("caustics.spheres")),
                            rg::Access::StorageWrite);
        f.instances = b.write(b.createBuffer("caustics.sphereInstances",
                                             rhi::BufferDesc().setByteSize(uint64_t(pixels) * sizeof(rhi::InstanceDesc))
                                                 .setUsage(rhi::BufferUsage::Storage | rhi::BufferUsage::AccelStructInput)
                                                 .setDebugName("caustics.sphereInstances")),
                              rg::Access::StorageWrite);
        f.stats = b.write(f.stats, rg::Access::StorageReadWrite);
        uint64_t blas = res.sphereBlas->deviceAddress();
        // Mirrors the push block of shaders/vulkan/backward_trace/backward.rgen.
        struct Push {
            uint32_t policy;
            float scale, worldRadius;
            uint32_t maxDepth, frame, blasLo, blasHi;
            float minMagnification, maxMagnification, minRadius, maxRadius;
            uint32_t pad;
        } push{s.sphereRadiusPolicy == SphereRadiusPolicy::PixelFootprint ? 0u : 1u,
               s.sphereRadiusScale,
               s.sphereWorldRadius,
               s.maxSpecularDepth,
               f.in->frameIndex * 0x9E3779B9u + s.seed,
               uint32_t(blas),
               uint32_t(blas >> 32),
               s.sphereMinMagnification,
               s.sphereMaxMagnification,
               s.sphereMinRadius,
               s.sphereMaxRadius,
               0};
        static_assert(sizeof(Push) == kBackwardPushBytes);
        CausticFrame h = f;
        rhi::BindingSetHandle sceneSet = f.in->sceneBindings->set;
        return [=](rg::PassContext& ctx) {
            CausticResources::Impl& r = *h.res;
            rhi::BindingSetDesc d;
            d.add(rhi::BindingSetItem::constantBuffer(0, ctx.buffer(h.camera)))
                .add(rhi::BindingSetItem::sampledTexture(1, ctx.texture(objectId)))
                .add(rhi::BindingSetItem::sampledTexture(2, ctx.texture(optics)))
                .add(rhi::BindingSetItem::storageBuffer(3, ctx.buffer(h.spheres)))
                .add(rhi::BindingSetItem::storageBuffer(4, ctx.buffer(h.instances)))
                .add(rhi::BindingSetItem::storageBuffer(5, ctx.buffer(h.stats)));
            rhi::BindingSetHandle set = r.makeSet(*ctx.device(), r.backwardLayout, d);
            if (!set) return;
            recordSceneTrace(ctx.cmd(), r.backwardState, r.backwardTable, sceneSet, set, push, h.width, h.height, 1);
        };
    });

    rg::RgAccelStruct blas = graph.importAccelStruct("caustics.sphereBlas", res.sphereBlas, rhi::ResourceState::AccelStructRead,
                                                     rhi::ResourceState::AccelStructRead);
    f.sphereTlas = graph.importAccelStruct("caustics.sphereTlas", res.sphereTlas, rhi::ResourceState::AccelStructRead,
                                           rhi::ResourceState::AccelStructRead);
    graph.addPass("caustics.spheres", [&](rg::PassBuilder& b) {
        f.instances = b.read(f.instances, rg::Access::AccelStructBuildInput);
        b.read(blas, rg::Access::AccelStructBuildRead);
        f.sphereTlas = b.write(f.sphereTlas, rg::Access::AccelStructBuild);
        CausticFrame h = f;
        return [=](rg::PassContext& ctx) {
            ctx.cmd().buildTopLevelFromBuffer(ctx.accelStruct(h.sphereTlas), ctx.buffer(h.instances), 0, pixels);
        };
    });

    // The gather's grid is the stored-hit count (clamped to the buffer), counted on the GPU.
    const bool indirect = res.device->capabilities().rayTracingIndirect;
    rg::RgBuffer gatherGrid;
    if (indirect)
        gatherGrid = addGridFromCountPass(graph, f, "caustics.gatherGrid", kStatStoredHitAttempts,
                                          f.in->settings.maxStoredHits);
    graph.addPass("caustics.gather", [&](rg::PassBuilder& b) {
        if (indirect) gatherGrid = b.read(gatherGrid, rg::Access::IndirectArgument);
        f.sphereTlas = b.read(f.sphereTlas, rg::Access::AccelStructTrace);
        f.spheres = b.read(f.spheres, rg::Access::SampledRead);
        f.hits = b.read(f.hits, rg::Access::SampledRead);
        f.stats = b.write(f.stats, rg::Access::StorageReadWrite);
        f.radiance2 = b.write(f.radiance2, rg::Access::StorageReadWrite);
        uint32_t maxHits = f.in->settings.maxStoredHits;
        CausticFrame h = f;
        return [=](rg::PassContext& ctx) {
            CausticResources::Impl& r = *h.res;
            rhi::BindingSetDesc d;
            d.add(rhi::BindingSetItem::accelStructItem(0, ctx.accelStruct(h.sphereTlas)))
                .add(rhi::BindingSetItem::storageBuffer(1, ctx.buffer(h.spheres), false))
                .add(rhi::BindingSetItem::storageBuffer(2, ctx.buffer(h.hits), false))
                .add(rhi::BindingSetItem::storageBuffer(3, ctx.buffer(h.stats)))
                .add(rhi::BindingSetItem::storageBuffer(4, ctx.buffer(h.radiance2)));
            rhi::BindingSetHandle set = r.makeSet(*ctx.device(), r.gatherLayout, d);
            if (!set) return;
            rhi::ICommandList& cmd = ctx.cmd();
            cmd.setRayTracingState(r.gatherState, r.gatherTable);
            cmd.setBindingSet(0, set);
            cmd.setPushConstants(&maxHits, 4);
            // Without indirect dispatch: launched for the buffer's capacity; launches past the stored
            // count return at once.
            if (indirect) cmd.dispatchRaysIndirect(ctx.buffer(gatherGrid));
            else cmd.dispatchRays(maxHits, 1, 1);
        };
    });
}

}  // namespace caustics
