// caustics.resolve (radiance buffers -> textures) and the caustic filter (paper 3.4, built as SVGF,
// Schied et al. 2017; docs/caustics.md "Filter"):
//   caustics.temporal   reprojected history, disocclusion tests, 1/n average up to the history cap
//   caustics.history    next frame's history: the temporal result (unfiltered), moments, G-buffer guides
//   caustics.variance   luminance variance: temporal moments, or photon shot noise for short histories
//   caustics.atrous.N   edge-aware a-trous iterations stopping at depth, normal, object and luminance:
//                       .weights (each source's weight sum), then the spreading (energy-preserving)
// With settings.filter off the combined radiance is returned unfiltered.
#include <string>

#include "caustic_maps/caustic_internal.h"

namespace caustics {
namespace {

rhi::TextureDesc imageDesc(uint32_t w, uint32_t h, const char* name) {
    return rhi::TextureDesc().setSize(w, h).setFormat(rhi::Format::RGBA32_FLOAT)
        .setUsage(rhi::TextureUsage::Sampled | rhi::TextureUsage::Storage | rhi::TextureUsage::CopySource)
        .setDebugName(name);
}

// Sampled textures at slots first, first + 1, ..., then the storage images after them.
rhi::BindingSetDesc textureBindings(rg::PassContext& ctx, uint32_t first, std::initializer_list<rg::RgTexture> sampled,
                                    std::initializer_list<rg::RgTexture> storage) {
    rhi::BindingSetDesc d;
    uint32_t slot = first;
    for (rg::RgTexture t : sampled) d.add(rhi::BindingSetItem::sampledTexture(slot++, ctx.texture(t)));
    for (rg::RgTexture t : storage) d.add(rhi::BindingSetItem::storageTexture(slot++, ctx.texture(t)));
    return d;
}

// One 8x8-group compute dispatch over the image; false (nothing recorded) when the binding set failed.
template <typename Push>
bool dispatchImage(rg::PassContext& ctx, CausticResources::Impl& r, const rhi::ComputePipelineHandle& pipeline,
                   const rhi::BindingLayoutHandle& layout, rhi::BindingSetDesc bindings, const Push& push, uint32_t w,
                   uint32_t h) {
    rhi::BindingSetHandle set = r.makeSet(*ctx.device(), layout, std::move(bindings));
    if (!set) return false;
    ctx.cmd().setComputePipeline(pipeline);
    ctx.cmd().setBindingSet(0, set);
    ctx.cmd().setPushConstants(&push, sizeof(push));
    ctx.cmd().dispatch((w + 7) / 8, (h + 7) / 8);
    return true;
}

// Resolve push flag (shaders/*/caustic_filter/resolve.*): one buffer holds both types, write only the sum.
constexpr uint32_t kResolveCombinedOnly = 2u;

void addResolvePass(rg::RenderGraph& graph, CausticFrame& f, CausticOutputs& out) {
    const uint32_t w = f.width, h = f.height;
    graph.addPass("caustics.resolve", [&](rg::PassBuilder& b) {
        // One buffer for both types (CausticFrameInputs::separateTypes off): it is bound twice and the
        // radiance texture in all three image slots; the shader writes only the sum.
        const bool separate = f.separateTypes;
        f.radiance1 = b.read(f.radiance1, rg::Access::SampledRead);
        if (separate) {
            f.radiance2 = b.read(f.radiance2, rg::Access::SampledRead);
            out.firstType = b.write(b.createTexture("caustics.firstType", imageDesc(w, h, "caustics.firstType")));
            out.secondType = b.write(b.createTexture("caustics.secondType", imageDesc(w, h, "caustics.secondType")));
        }
        out.radiance = b.write(b.createTexture("caustics.radiance", imageDesc(w, h, "caustics.radiance")));
        CausticFrame fr = f;
        CausticOutputs o = out;
        struct { uint32_t width, height, flags; float invScale; } push{
            w, h, (f.res->floatAtomics ? 0u : 1u) | (separate ? 0u : kResolveCombinedOnly) | (f.wideFixedPoint ? 4u : 0u),
            1.0f / f.fixedPointScale};
        return [=](rg::PassContext& ctx) {
            rhi::BindingSetDesc d = separate ? textureBindings(ctx, 2, {}, {o.firstType, o.secondType, o.radiance})
                                             : textureBindings(ctx, 2, {}, {o.radiance, o.radiance, o.radiance});
            d.add(rhi::BindingSetItem::storageBuffer(0, ctx.buffer(fr.radiance1), false))
                .add(rhi::BindingSetItem::storageBuffer(1, ctx.buffer(separate ? fr.radiance2 : fr.radiance1), false));
            dispatchImage(ctx, *fr.res, fr.res->filter.resolve, fr.res->filter.resolveLayout, d, push, w, h);
        };
    });
}

struct HistoryHandles {
    rg::RgTexture color, moments, depth, normal, id;
};

HistoryHandles importHistory(rg::RenderGraph& graph, const CausticViewHistory& history) {
    const rhi::ResourceState ro = rhi::ResourceState::ShaderResource;
    const rhi::ResourceState now = history.valid ? ro : rhi::ResourceState::Undefined;
    return {graph.importTexture("caustics.historyColor", history.color, now, ro),
            graph.importTexture("caustics.historyMoments", history.moments, now, ro),
            graph.importTexture("caustics.historyDepth", history.depth, now, ro),
            graph.importTexture("caustics.historyNormal", history.normal, now, ro),
            graph.importTexture("caustics.historyObjectId", history.objectId, now, ro)};
}

// Iteration i (step 2^i) on `radiance` (rgb, a = variance), which it replaces with its result.
void addAtrousIteration(rg::RenderGraph& graph, CausticFrame& f, uint32_t i, rg::RgTexture& radiance) {
    const uint32_t w = f.width, h = f.height;
    const GBuffer& g = f.in->gbuffer;
    const CausticsSettings& s = f.in->settings;
    const std::string name = "caustics.atrous." + std::to_string(i);
    const int32_t step = 1 << i;
    rg::RgTexture sources;
    graph.addPass(name + ".weights", [&](rg::PassBuilder& b) {
        const rg::RgTexture in[] = {b.read(radiance), b.read(g.linearDepth), b.read(g.normalRoughness), b.read(g.objectId)};
        sources = b.write(b.createTexture(name + ".weights", imageDesc(w, h, "caustics.atrousWeights")));
        CausticFrame fr = f;
        rg::RgTexture o = sources;
        struct { int32_t stepWidth, width, height; float sigmaLuminance; } push{step, int32_t(w), int32_t(h),
                                                                               s.filterLuminanceSigma};
        return [=](rg::PassContext& ctx) {
            rhi::BindingSetDesc d = textureBindings(ctx, 0, {in[0], in[1], in[2], in[3]}, {o});
            dispatchImage(ctx, *fr.res, fr.res->filter.atrousWeights, fr.res->filter.atrousWeightsLayout, d, push, w, h);
        };
    });
    graph.addPass(name, [&](rg::PassBuilder& b) {
        const rg::RgTexture in[] = {b.read(radiance), b.read(sources), b.read(g.linearDepth), b.read(g.normalRoughness),
                                    b.read(g.objectId)};
        radiance = b.write(b.createTexture(name, imageDesc(w, h, "caustics.atrous")));
        CausticFrame fr = f;
        rg::RgTexture o = radiance;
        struct { int32_t stepWidth, width, height; float sigmaLuminance; uint32_t lastIteration; } push{
            step, int32_t(w), int32_t(h), s.filterLuminanceSigma, i + 1 == s.atrousIterations ? 1u : 0u};
        return [=](rg::PassContext& ctx) {
            rhi::BindingSetDesc d = textureBindings(ctx, 0, {in[0], in[1], in[2], in[3], in[4]}, {o});
            dispatchImage(ctx, *fr.res, fr.res->filter.atrous, fr.res->filter.atrousLayout, d, push, w, h);
        };
    });
}

}  // namespace

void addResolveAndFilterPasses(rg::RenderGraph& graph, CausticFrame& f, CausticOutputs& out) {
    addResolvePass(graph, f, out);
    const CausticsSettings& s = f.in->settings;
    if (!s.filter) return;

    const uint32_t w = f.width, h = f.height;
    const GBuffer& g = f.in->gbuffer;
    // The view's history (caustic_passes.h): valid only after an executed frame of this view.
    HistoryHandles hist = importHistory(graph, *f.history);
    const bool historyUsable = f.history->valid && !f.in->resetHistory;
    const rg::RgTexture raw = out.radiance;

    rg::RgTexture color, moments;
    graph.addPass("caustics.temporal", [&](rg::PassBuilder& b) {
        f.camera = b.read(f.camera, rg::Access::ConstantBuffer);
        const rg::RgTexture in[] = {b.read(raw), b.read(g.linearDepth), b.read(g.normalRoughness), b.read(g.objectId),
                                    b.read(hist.color), b.read(hist.moments), b.read(hist.depth), b.read(hist.normal),
                                    b.read(hist.id)};
        color = b.write(b.createTexture("caustics.temporal", imageDesc(w, h, "caustics.temporal")));
        moments = b.write(b.createTexture("caustics.moments", imageDesc(w, h, "caustics.moments")));
        CausticFrame fr = f;
        rg::RgTexture c = color, m = moments;
        struct { uint32_t historyValid; float maxHistory; } push{historyUsable ? 1u : 0u, float(s.filterMaxHistory)};
        return [=](rg::PassContext& ctx) {
            rhi::BindingSetDesc d = textureBindings(ctx, 1, {in[0], in[1], in[2], in[3], in[4], in[5], in[6], in[7], in[8]},
                                                    {c, m});
            d.add(rhi::BindingSetItem::constantBuffer(0, ctx.buffer(fr.camera)));
            dispatchImage(ctx, *fr.res, fr.res->filter.temporal, fr.res->filter.temporalLayout, d, push, w, h);
        };
    });

    graph.addPass("caustics.history", [&](rg::PassBuilder& b) {
        const rg::RgTexture in[] = {b.read(color), b.read(moments), b.read(g.linearDepth), b.read(g.normalRoughness),
                                    b.read(g.objectId)};
        hist = {b.write(hist.color), b.write(hist.moments), b.write(hist.depth), b.write(hist.normal), b.write(hist.id)};
        CausticFrame fr = f;
        HistoryHandles o = hist;
        int32_t push[2] = {int32_t(w), int32_t(h)};
        return [=](rg::PassContext& ctx) {
            rhi::BindingSetDesc d = textureBindings(ctx, 0, {in[0], in[1], in[2], in[3], in[4]},
                                                    {o.color, o.moments, o.depth, o.normal, o.id});
            if (dispatchImage(ctx, *fr.res, fr.res->filter.history, fr.res->filter.historyLayout, d, push, w, h))
                fr.history->valid = true;   // committed when recorded, not when the graph was built
        };
    });
    // Nothing reads the history this frame: mark it as an output so the pass is not culled.
    graph.markOutput(hist.color);

    out.radiance = color;
    if (s.atrousIterations == 0) return;
    graph.addPass("caustics.variance", [&](rg::PassBuilder& b) {
        const rg::RgTexture in[] = {b.read(raw), b.read(color), b.read(moments), b.read(g.objectId)};
        out.radiance = b.write(b.createTexture("caustics.variance", imageDesc(w, h, "caustics.variance")));
        CausticFrame fr = f;
        rg::RgTexture o = out.radiance;
        int32_t push[2] = {int32_t(w), int32_t(h)};
        return [=](rg::PassContext& ctx) {
            rhi::BindingSetDesc d = textureBindings(ctx, 0, {in[0], in[1], in[2], in[3]}, {o});
            dispatchImage(ctx, *fr.res, fr.res->filter.variance, fr.res->filter.varianceLayout, d, push, w, h);
        };
    });

    for (uint32_t i = 0; i < s.atrousIterations; ++i) addAtrousIteration(graph, f, i, out.radiance);
}

}  // namespace caustics
