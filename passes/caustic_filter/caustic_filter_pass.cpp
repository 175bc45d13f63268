// caustics.resolve (buffers -> textures) and the filter of paper 3.4: caustics.temporal (reprojected
// history), caustics.atrous.N (edge-aware a-trous iterations) and caustics.history (next frame's
// history). With settings.filter off the combined radiance is returned unfiltered.
#include "caustic_maps/caustic_internal.h"

namespace caustics {
namespace {

rhi::TextureDesc imageDesc(uint32_t w, uint32_t h, const char* name) {
    return rhi::TextureDesc().setSize(w, h).setFormat(rhi::Format::RGBA32_FLOAT)
        .setUsage(rhi::TextureUsage::Sampled | rhi::TextureUsage::Storage | rhi::TextureUsage::CopySource)
        .setDebugName(name);
}

uint32_t groups(uint32_t n) { return (n + 7) / 8; }

}  // namespace

void addResolveAndFilterPasses(rg::RenderGraph& graph, CausticFrame& f, CausticOutputs& out) {
    const uint32_t w = f.width, hgt = f.height;
    graph.addPass("caustics.resolve", [&](rg::PassBuilder& b) {
        f.radiance1 = b.read(f.radiance1, rg::Access::SampledRead);
        f.radiance2 = b.read(f.radiance2, rg::Access::SampledRead);
        out.firstType = b.write(b.createTexture("caustics.firstType", imageDesc(w, hgt, "caustics.firstType")));
        out.secondType = b.write(b.createTexture("caustics.secondType", imageDesc(w, hgt, "caustics.secondType")));
        out.radiance = b.write(b.createTexture("caustics.radiance", imageDesc(w, hgt, "caustics.radiance")));
        CausticFrame h = f;
        CausticOutputs o = out;
        uint32_t push[4] = {w, hgt, f.res->floatAtomics ? 0u : 1u, 0};
        return [=](rg::PassContext& ctx) {
            CausticResources::Impl& r = *h.res;
            rhi::BindingSetDesc d;
            d.add(rhi::BindingSetItem::storageBuffer(0, ctx.buffer(h.radiance1), false))
                .add(rhi::BindingSetItem::storageBuffer(1, ctx.buffer(h.radiance2), false))
                .add(rhi::BindingSetItem::storageTexture(2, ctx.texture(o.firstType)))
                .add(rhi::BindingSetItem::storageTexture(3, ctx.texture(o.secondType)))
                .add(rhi::BindingSetItem::storageTexture(4, ctx.texture(o.radiance)));
            rhi::BindingSetHandle set = r.makeSet(*ctx.device(), r.resolveLayout, d);
            if (!set) return;
            ctx.cmd().setComputePipeline(r.resolve);
            ctx.cmd().setBindingSet(0, set);
            ctx.cmd().setPushConstants(push, sizeof(push));
            ctx.cmd().dispatch(groups(w), groups(hgt));
        };
    });
    if (!f.in->settings.filter) return;

    // The view's history (caustic_passes.h): valid only after an executed frame of this view.
    CausticViewHistory& hist = *f.history;
    const GBuffer& g = f.in->gbuffer;
    const rhi::ResourceState histState = hist.valid ? rhi::ResourceState::ShaderResource : rhi::ResourceState::Undefined;
    const rhi::ResourceState ro = rhi::ResourceState::ShaderResource;
    rg::RgTexture hColor = graph.importTexture("caustics.historyColor", hist.color, histState, ro);
    rg::RgTexture hDepth = graph.importTexture("caustics.historyDepth", hist.depth, histState, ro);
    rg::RgTexture hNormal = graph.importTexture("caustics.historyNormal", hist.normal, histState, ro);
    rg::RgTexture hId = graph.importTexture("caustics.historyObjectId", hist.objectId, histState, ro);
    const bool historyUsable = hist.valid && !f.in->resetHistory;

    rg::RgTexture temporal;
    graph.addPass("caustics.temporal", [&](rg::PassBuilder& b) {
        f.camera = b.read(f.camera, rg::Access::ConstantBuffer);
        rg::RgTexture cur = b.read(out.radiance, rg::Access::SampledRead);
        rg::RgTexture ld = b.read(g.linearDepth), nr = b.read(g.normalRoughness), id = b.read(g.objectId);
        rg::RgTexture hc = b.read(hColor), hd = b.read(hDepth), hn = b.read(hNormal), hi = b.read(hId);
        temporal = b.write(b.createTexture("caustics.temporal", imageDesc(w, hgt, "caustics.temporal")));
        rg::RgTexture t = temporal;
        CausticFrame h = f;
        struct { float alpha; uint32_t valid; } push{f.in->settings.temporalAlpha, historyUsable ? 1u : 0u};
        return [=](rg::PassContext& ctx) {
            CausticResources::Impl& r = *h.res;
            rhi::BindingSetDesc d;
            d.add(rhi::BindingSetItem::constantBuffer(0, ctx.buffer(h.camera)));
            uint32_t slot = 1;
            for (rg::RgTexture x : {cur, ld, nr, id, hc, hd, hn, hi}) d.add(rhi::BindingSetItem::sampledTexture(slot++, ctx.texture(x)));
            d.add(rhi::BindingSetItem::storageTexture(9, ctx.texture(t)));
            rhi::BindingSetHandle set = r.makeSet(*ctx.device(), r.temporalLayout, d);
            if (!set) return;
            ctx.cmd().setComputePipeline(r.temporal);
            ctx.cmd().setBindingSet(0, set);
            ctx.cmd().setPushConstants(&push, sizeof(push));
            ctx.cmd().dispatch(groups(w), groups(hgt));
        };
    });

    graph.addPass("caustics.history", [&](rg::PassBuilder& b) {
        rg::RgTexture t = b.read(temporal);
        rg::RgTexture ld = b.read(g.linearDepth), nr = b.read(g.normalRoughness), id = b.read(g.objectId);
        rg::RgTexture hc = b.write(hColor), hd = b.write(hDepth), hn = b.write(hNormal), hi = b.write(hId);
        CausticFrame h = f;
        return [=](rg::PassContext& ctx) {
            CausticResources::Impl& r = *h.res;
            rhi::BindingSetDesc d;
            uint32_t slot = 0;
            for (rg::RgTexture x : {t, ld, nr, id}) d.add(rhi::BindingSetItem::sampledTexture(slot++, ctx.texture(x)));
            for (rg::RgTexture x : {hc, hd, hn, hi}) d.add(rhi::BindingSetItem::storageTexture(slot++, ctx.texture(x)));
            rhi::BindingSetHandle set = r.makeSet(*ctx.device(), r.historyLayout, d);
            if (!set) return;
            int32_t push[2] = {int32_t(w), int32_t(hgt)};
            ctx.cmd().setComputePipeline(r.history);
            ctx.cmd().setBindingSet(0, set);
            ctx.cmd().setPushConstants(push, sizeof(push));
            ctx.cmd().dispatch(groups(w), groups(hgt));
            h.history->valid = true;   // committed when recorded, not when the graph was built
        };
    });
    // The history pass has no reader this frame: mark its products as outputs so it is not culled.
    graph.markOutput(hColor);

    rg::RgTexture current = temporal;
    for (uint32_t i = 0; i < f.in->settings.atrousIterations; ++i) {
        std::string name = "caustics.atrous." + std::to_string(i);
        graph.addPass(name, [&](rg::PassBuilder& b) {
            rg::RgTexture in = b.read(current);
            rg::RgTexture ld = b.read(g.linearDepth), nr = b.read(g.normalRoughness), id = b.read(g.objectId);
            rg::RgTexture o = b.write(b.createTexture(name, imageDesc(w, hgt, "caustics.atrous")));
            current = o;
            CausticFrame h = f;
            int32_t push[4] = {1 << i, int32_t(w), int32_t(hgt), 0};
            return [=](rg::PassContext& ctx) {
                CausticResources::Impl& r = *h.res;
                rhi::BindingSetDesc d;
                uint32_t slot = 0;
                for (rg::RgTexture x : {in, ld, nr, id}) d.add(rhi::BindingSetItem::sampledTexture(slot++, ctx.texture(x)));
                d.add(rhi::BindingSetItem::storageTexture(4, ctx.texture(o)));
                rhi::BindingSetHandle set = r.makeSet(*ctx.device(), r.atrousLayout, d);
                if (!set) return;
                ctx.cmd().setComputePipeline(r.atrous);
                ctx.cmd().setBindingSet(0, set);
                ctx.cmd().setPushConstants(push, sizeof(push));
                ctx.cmd().dispatch(groups(w), groups(hgt));
            };
        });
    }
    out.radiance = current;
}

}  // namespace caustics
