// caustics.resolve (radiance buffers -> textures) and the caustic filter (paper 3.4, built as SVGF,
// Schied et al. 2017; docs/caustics.md "Filter"), every filter pass dispatched indirectly over a list of
// the 8x8 tiles that received photons or still hold history (docs/caustics.md "Tiles"):
//   caustics.filterTiles  the view's tile state (how long each tile's history is kept); .list the tiles
//   caustics.temporal   reprojected history, disocclusion tests, 1/n average up to the history cap; writes
//                       this frame's copy of the ping-ponged history (the result, unfiltered, its second
//                       moment) and the packed guides (depth, gradient, normal, object id) read below
//   caustics.variance   luminance variance: temporal moments, or photon shot noise for short histories
//   caustics.atrous.N   edge-aware a-trous iterations stopping at depth, normal, object and luminance:
//                       .weights (each source's weight sum), then the spreading (energy-preserving)
//   caustics.filterOutput  (atrousIterations 0 only) the temporal result into caustics.radiance
// The last pass writes into caustics.radiance, over the listed tiles (the others hold this frame's zeros).
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

// Binds a filter pipeline with its set and push constants; false (nothing bound) when the set failed.
template <typename Push>
bool bindFilter(rg::PassContext& ctx, CausticResources::Impl& r, const rhi::ComputePipelineHandle& pipeline,
                const rhi::BindingLayoutHandle& layout, rhi::BindingSetDesc bindings, const Push& push) {
    rhi::BindingSetHandle set = r.makeSet(*ctx.device(), layout, std::move(bindings));
    if (!set) return false;
    ctx.cmd().setComputePipeline(pipeline);
    ctx.cmd().setBindingSet(0, set);
    ctx.cmd().setPushConstants(&push, sizeof(push));
    return true;
}

// One 8x8-group compute dispatch over the image.
template <typename Push>
bool dispatchImage(rg::PassContext& ctx, CausticResources::Impl& r, const rhi::ComputePipelineHandle& pipeline,
                   const rhi::BindingLayoutHandle& layout, rhi::BindingSetDesc bindings, const Push& push, uint32_t w,
                   uint32_t h) {
    if (!bindFilter(ctx, r, pipeline, layout, std::move(bindings), push)) return false;
    ctx.cmd().dispatch((w + 7) / 8, (h + 7) / 8);
    return true;
}

// Resolve push flag (shaders/*/caustic_filter/resolve.*): one buffer holds both types, write only the sum.
constexpr uint32_t kResolveCombinedOnly = 2u;
// The filter's tile list (tiles.comp; docs/caustics.md "Filter", "Tiles"): `args` (listed tiles, 1, 1)
// for the indirect dispatches, `list` the packed tiles, `state` this frame's tile state (history's).
struct FilterTiles {
    rg::RgBuffer args, list;
    rg::RgTexture state;
};

// One 8x8 group per listed tile, the group count read from the tile list's arguments.
template <typename Push>
bool dispatchTiles(rg::PassContext& ctx, CausticResources::Impl& r, const rhi::ComputePipelineHandle& pipeline,
                   const rhi::BindingLayoutHandle& layout, rhi::BindingSetDesc bindings, const Push& push,
                   rg::RgBuffer args) {
    if (!bindFilter(ctx, r, pipeline, layout, std::move(bindings), push)) return false;
    ctx.cmd().dispatchIndirect(ctx.buffer(args));
    return true;
}

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

// The view's ping-ponged history (caustic_passes.h): last frame's (read) and this frame's (written).
struct HistoryHandles {
    rg::RgTexture previousColor, previousMoments, previousGuides, previousTiles;
    rg::RgTexture color, moments, guides, tiles;
};

HistoryHandles importHistory(rg::RenderGraph& graph, const CausticViewHistory& history) {
    const rhi::ResourceState ro = rhi::ResourceState::ShaderResource;
    const rhi::ResourceState now = history.builtValid ? ro : rhi::ResourceState::Undefined;
    auto import = [&](const char* name, const rhi::TextureHandle (&t)[2], uint32_t i) {
        return graph.importTexture(std::string(name) + std::to_string(i), t[i], now, ro);
    };
    const uint32_t previous = history.builtParity, next = history.builtParity ^ 1u;
    return {import("caustics.historyColor", history.color, previous),
            import("caustics.historyMoments", history.moments, previous),
            import("caustics.historyGuides", history.guides, previous),
            import("caustics.historyTiles", history.tiles, previous),
            import("caustics.historyColor", history.color, next),
            import("caustics.historyMoments", history.moments, next),
            import("caustics.historyGuides", history.guides, next),
            import("caustics.historyTiles", history.tiles, next)};
}

// caustics.filterTiles: this frame's tile state (tiles.comp), then caustics.filterTiles.list clears the
// arguments to (0, 1, 1) and lists the tiles (tile_list.comp). Nothing after it runs on an unlisted tile.
FilterTiles addTilePasses(rg::RenderGraph& graph, CausticFrame& f, HistoryHandles& hist, rg::RgTexture raw,
                          bool historyUsable) {
    const uint32_t w = f.width, h = f.height, tilesX = (w + 7) / 8, tilesY = (h + 7) / 8;
    FilterTiles t;
    graph.addPass("caustics.filterTiles", [&](rg::PassBuilder& b) {
        f.camera = b.read(f.camera, rg::Access::ConstantBuffer);
        const GBuffer& g = f.in->gbuffer;
        const rg::RgTexture in[] = {b.read(raw), b.read(g.linearDepth), b.read(g.objectId), b.read(hist.previousTiles)};
        hist.tiles = b.write(hist.tiles);
        CausticFrame fr = f;
        rg::RgTexture o = hist.tiles;
        struct { uint32_t historyValid, keepFrames; } push{historyUsable ? 1u : 0u, f.in->settings.filterMaxHistory};
        return [=](rg::PassContext& ctx) {
            rhi::BindingSetDesc d = textureBindings(ctx, 1, {in[0], in[1], in[2], in[3]}, {o});
            d.add(rhi::BindingSetItem::constantBuffer(0, ctx.buffer(fr.camera)));
            if (bindFilter(ctx, *fr.res, fr.res->filter.tiles, fr.res->filter.tilesLayout, d, push))
                ctx.cmd().dispatch(tilesX, tilesY);   // one group per tile
        };
    });
    graph.addPass("caustics.filterTiles.clear", [&](rg::PassBuilder& b) {
        t.args = b.write(b.createBuffer("caustics.filterTileArgs",
                                        rhi::BufferDesc().setByteSize(12)
                                            .setUsage(rhi::BufferUsage::Storage | rhi::BufferUsage::Indirect |
                                                      rhi::BufferUsage::CopyDest | rhi::BufferUsage::CopySource)
                                            .setDebugName("caustics.filterTileArgs")),
                         rg::Access::CopyDest);
        rg::RgBuffer args = t.args;
        return [=](rg::PassContext& ctx) {
            ctx.cmd().fillBuffer(ctx.buffer(args), 0u, 0, 4);
            ctx.cmd().fillBuffer(ctx.buffer(args), 1u, 4, 8);
        };
    });
    graph.addPass("caustics.filterTiles.list", [&](rg::PassBuilder& b) {
        hist.tiles = b.write(hist.tiles, rg::Access::StorageReadWrite);
        t.args = b.write(t.args, rg::Access::StorageReadWrite);
        t.list = b.write(b.createBuffer("caustics.filterTileList", rhi::BufferDesc().setByteSize(uint64_t(tilesX) * tilesY * 4)
                                                                      .setUsage(rhi::BufferUsage::Storage)
                                                                      .setDebugName("caustics.filterTileList")));
        t.state = hist.tiles;
        CausticFrame fr = f;
        FilterTiles o = t;
        int32_t push[2] = {int32_t(tilesX), int32_t(tilesY)};
        return [=](rg::PassContext& ctx) {
            rhi::BindingSetDesc d;
            d.add(rhi::BindingSetItem::storageTexture(0, ctx.texture(o.state)))
                .add(rhi::BindingSetItem::storageBuffer(1, ctx.buffer(o.args)))
                .add(rhi::BindingSetItem::storageBuffer(2, ctx.buffer(o.list)));
            dispatchImage(ctx, *fr.res, fr.res->filter.tileList, fr.res->filter.tileListLayout, d, push, tilesX, tilesY);
        };
    });
    // The next frame reads the tile state: never culled.
    graph.markOutput(hist.tiles);
    return t;
}

// The tile list bindings of a pass dispatched over it: the arguments (indirect) and the list.
void readTiles(rg::PassBuilder& b, FilterTiles& t, bool state) {
    t.args = b.read(t.args, rg::Access::IndirectArgument);
    t.list = b.read(t.list);
    if (state) t.state = b.read(t.state);
}

// Iteration i (step 2^i) on `radiance` (rgb, a = variance), which it replaces with its result; the last
// iteration writes into `output` (caustics.radiance) instead.
void addAtrousIteration(rg::RenderGraph& graph, CausticFrame& f, uint32_t i, FilterTiles& tiles, rg::RgTexture guides,
                        rg::RgTexture& radiance, rg::RgTexture& output) {
    const uint32_t w = f.width, h = f.height;
    const CausticsSettings& s = f.in->settings;
    const std::string name = "caustics.atrous." + std::to_string(i);
    const int32_t step = 1 << i;
    const bool last = i + 1 == s.atrousIterations;
    rg::RgTexture sources;
    graph.addPass(name + ".weights", [&](rg::PassBuilder& b) {
        const rg::RgTexture in[] = {b.read(radiance), b.read(guides)};
        readTiles(b, tiles, true);
        sources = b.write(b.createTexture(name + ".weights", imageDesc(w, h, "caustics.atrousWeights")
                                                                 .setFormat(rhi::Format::R32_FLOAT)));
        CausticFrame fr = f;
        rg::RgTexture o = sources;
        FilterTiles t = tiles;
        struct { int32_t stepWidth, width, height; float sigmaLuminance; } push{step, int32_t(w), int32_t(h),
                                                                               s.filterLuminanceSigma};
        return [=](rg::PassContext& ctx) {
            rhi::BindingSetDesc d = textureBindings(ctx, 0, {in[0], in[1]}, {o});
            d.add(rhi::BindingSetItem::storageBuffer(3, ctx.buffer(t.list), false))
                .add(rhi::BindingSetItem::sampledTexture(4, ctx.texture(t.state)));
            dispatchTiles(ctx, *fr.res, fr.res->filter.atrousWeights, fr.res->filter.atrousWeightsLayout, d, push, t.args);
        };
    });
    graph.addPass(name, [&](rg::PassBuilder& b) {
        const rg::RgTexture in[] = {b.read(radiance), b.read(sources), b.read(guides)};
        readTiles(b, tiles, true);
        if (last) radiance = output = b.write(output);
        else radiance = b.write(b.createTexture(name, imageDesc(w, h, "caustics.atrous")));
        CausticFrame fr = f;
        rg::RgTexture o = radiance;
        FilterTiles t = tiles;
        struct { int32_t stepWidth, width, height; float sigmaLuminance; uint32_t lastIteration; } push{
            step, int32_t(w), int32_t(h), s.filterLuminanceSigma, last ? 1u : 0u};
        return [=](rg::PassContext& ctx) {
            rhi::BindingSetDesc d = textureBindings(ctx, 0, {in[0], in[1], in[2]}, {o});
            d.add(rhi::BindingSetItem::storageBuffer(4, ctx.buffer(t.list), false))
                .add(rhi::BindingSetItem::sampledTexture(5, ctx.texture(t.state)));
            dispatchTiles(ctx, *fr.res, fr.res->filter.atrous, fr.res->filter.atrousLayout, d, push, t.args);
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
    // The view's history (caustic_passes.h): valid only after an executed frame of this view. A
    // previous build that never executed and is superseded (same or earlier frame) is undone first.
    CausticViewHistory& vh = *f.history;
    const uint32_t frameIndex = f.in->frameIndex;
    if (vh.lastBuiltFrame && vh.lastBuiltFrame != vh.lastExecutedFrame && frameIndex <= *vh.lastBuiltFrame) {
        vh.builtParity = vh.parityBeforeLastBuild;
        vh.builtValid = vh.validBeforeLastBuild;
    }
    vh.parityBeforeLastBuild = vh.builtParity;
    vh.validBeforeLastBuild = vh.builtValid;
    vh.lastBuiltFrame = frameIndex;
    HistoryHandles hist = importHistory(graph, *f.history);
    const bool historyUsable = f.history->builtValid && !f.in->resetHistory;
    // The next graph built reads what this one writes (caustic_passes.h, CausticViewHistory::builtParity).
    const uint32_t readCopy = f.history->builtParity;
    f.history->builtParity ^= 1u;
    f.history->builtValid = true;
    // caustics.resolve's combined radiance: this frame's photons, zero in every tile the list leaves out;
    // the filter's last pass writes its result into it over the listed tiles.
    const rg::RgTexture raw = out.radiance;
    FilterTiles tiles = addTilePasses(graph, f, hist, raw, historyUsable);
    out.filterTiles = tiles.args;

    graph.addPass("caustics.temporal", [&](rg::PassBuilder& b) {
        f.camera = b.read(f.camera, rg::Access::ConstantBuffer);
        const rg::RgTexture in[] = {b.read(raw), b.read(g.linearDepth), b.read(g.normalRoughness), b.read(g.objectId),
                                    b.read(hist.previousColor), b.read(hist.previousMoments), b.read(hist.previousGuides),
                                    b.read(hist.previousTiles)};
        readTiles(b, tiles, false);
        hist.color = b.write(hist.color);
        hist.moments = b.write(hist.moments);
        hist.guides = b.write(hist.guides);
        CausticFrame fr = f;
        HistoryHandles o = hist;
        FilterTiles t = tiles;
        struct { uint32_t historyValid; float maxHistory; } built{historyUsable ? 1u : 0u, float(s.filterMaxHistory)};
        return [=](rg::PassContext& ctx) {
            // Only if the last EXECUTED frame wrote the copy this one reads (a dropped graph breaks it).
            auto push = built;
            push.historyValid &= (fr.history->valid && fr.history->parity == readCopy) ? 1u : 0u;
            rhi::BindingSetDesc d = textureBindings(ctx, 1, {in[0], in[1], in[2], in[3], in[4], in[5], in[6], in[7]}, {});
            d.add(rhi::BindingSetItem::constantBuffer(0, ctx.buffer(fr.camera)))
                .add(rhi::BindingSetItem::storageBuffer(9, ctx.buffer(t.list), false))
                .add(rhi::BindingSetItem::storageTexture(10, ctx.texture(o.color)))
                .add(rhi::BindingSetItem::storageTexture(11, ctx.texture(o.moments)))
                .add(rhi::BindingSetItem::storageTexture(12, ctx.texture(o.guides)));
            if (dispatchTiles(ctx, *fr.res, fr.res->filter.temporal, fr.res->filter.temporalLayout, d, push, t.args)) {
                // Committed when recorded, not when the graph was built: this frame's copy is the next
                // frame's previous one.
                fr.history->valid = true;
                fr.history->parity = readCopy ^ 1u;
                fr.history->lastExecutedFrame = frameIndex;
            }
        };
    });
    // The next frame reads the history: never culled.
    graph.markOutput(hist.color);
    graph.markOutput(hist.moments);
    graph.markOutput(hist.guides);
    const rg::RgTexture color = hist.color, moments = hist.moments;

    if (s.atrousIterations == 0) {
        graph.addPass("caustics.filterOutput", [&](rg::PassBuilder& b) {
            const rg::RgTexture in = b.read(color);
            readTiles(b, tiles, false);
            out.radiance = b.write(raw);
            CausticFrame fr = f;
            rg::RgTexture o = out.radiance;
            FilterTiles t = tiles;
            int32_t push[2] = {int32_t(w), int32_t(h)};
            return [=](rg::PassContext& ctx) {
                rhi::BindingSetDesc d = textureBindings(ctx, 0, {in}, {});
                d.add(rhi::BindingSetItem::storageBuffer(1, ctx.buffer(t.list), false))
                    .add(rhi::BindingSetItem::storageTexture(2, ctx.texture(o)));
                dispatchTiles(ctx, *fr.res, fr.res->filter.output, fr.res->filter.outputLayout, d, push, t.args);
            };
        });
        return;
    }
    rg::RgTexture radiance;
    graph.addPass("caustics.variance", [&](rg::PassBuilder& b) {
        const rg::RgTexture in[] = {b.read(raw), b.read(color), b.read(moments), b.read(g.objectId)};
        readTiles(b, tiles, true);
        radiance = b.write(b.createTexture("caustics.variance", imageDesc(w, h, "caustics.variance")));
        CausticFrame fr = f;
        rg::RgTexture o = radiance;
        FilterTiles t = tiles;
        int32_t push[2] = {int32_t(w), int32_t(h)};
        return [=](rg::PassContext& ctx) {
            rhi::BindingSetDesc d = textureBindings(ctx, 0, {in[0], in[1], in[2], in[3]}, {o});
            d.add(rhi::BindingSetItem::storageBuffer(5, ctx.buffer(t.list), false))
                .add(rhi::BindingSetItem::sampledTexture(6, ctx.texture(t.state)));
            dispatchTiles(ctx, *fr.res, fr.res->filter.variance, fr.res->filter.varianceLayout, d, push, t.args);
        };
    });

    out.radiance = raw;
    for (uint32_t i = 0; i < s.atrousIterations; ++i)
        addAtrousIteration(graph, f, i, tiles, hist.guides, radiance, out.radiance);
}

}  // namespace caustics
