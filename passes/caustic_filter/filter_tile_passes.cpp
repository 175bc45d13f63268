// The filter's tile passes and history import (filter_graph.h; docs/caustics.md "Filter", "Tiles",
// "Memory"): caustics.filterTiles (the view's tile state), .list (the tile list, each listed
// tile's pool tile) and .count (the tiles wanted, read back to size the pool).
#include <cmath>
#include <string>
#include <vector>

#include "caustic_filter/filter_graph.h"
#include "caustic_filter/shaders/tiles.h"
#include "caustic_filter/tiles_bindings.h"

namespace caustics::filter {

float filterPreExposure(const CausticFrame& f) {
    const float pre = f.in->settings.exposure * f.in->scene->exposure;
    return std::isfinite(pre) && pre > 0.0f ? pre : 1.0f;
}

HistoryHandles importHistory(rg::RenderGraph& graph, const CausticViewHistory& history) {
    const rhi::ResourceState ro = rhi::ResourceState::ShaderResource;
    const rhi::ResourceState now = history.builtValid ? ro : rhi::ResourceState::Undefined;
    // A grown pool's new textures hold nothing yet (the growth pass fills the copy this frame reads).
    const rhi::ResourceState pool = history.growth ? rhi::ResourceState::Undefined : now;
    auto import = [&](const char* name, const rhi::TextureHandle (&t)[2], uint32_t i, rhi::ResourceState state) {
        return graph.importTexture(std::string(name) + std::to_string(i), t[i], state, ro);
    };
    const uint32_t previous = history.builtParity, next = history.builtParity ^ 1u;
    return {import("caustics.historyColor", history.color, previous, pool),
            import("caustics.historyGuides", history.guides, previous, pool),
            import("caustics.historyTiles", history.tiles, previous, now),
            import("caustics.historySlots", history.slots, previous, now),
            import("caustics.historyColor", history.color, next, pool),
            import("caustics.historyGuides", history.guides, next, pool),
            import("caustics.historyTiles", history.tiles, next, now),
            import("caustics.historySlots", history.slots, next, now)};
}

void addPoolGrowthPass(rg::RenderGraph& graph, CausticFrame& f, HistoryHandles& hist, uint32_t readCopy, bool historyUsable) {
    CausticViewHistory& h = *f.history;
    if (!h.growth) return;
    CausticViewHistory::PoolGrowth growth = std::move(*h.growth);
    h.growth.reset();
    std::vector<rhi::TextureHandle>& retired = f.res->retiredTextures[f.res->frameSlot];
    for (uint32_t i = 0; i < 2; ++i) {
        retired.push_back(growth.color[i]);
        retired.push_back(growth.guides[i]);
    }
    if (!historyUsable) return;   // nothing to keep
    const rhi::ResourceState ro = rhi::ResourceState::ShaderResource;
    const rg::RgTexture oldColor = graph.importTexture("caustics.historyColorBeforeGrowth", growth.color[readCopy], ro, ro);
    const rg::RgTexture oldGuides = graph.importTexture("caustics.historyGuidesBeforeGrowth", growth.guides[readCopy], ro, ro);
    graph.addPass(filterPassName(f, "caustics.filterHistoryGrow"), [&](rg::PassBuilder& b) {
        const rg::RgTexture from[] = {b.read(oldColor, rg::Access::CopySource), b.read(oldGuides, rg::Access::CopySource)};
        hist.previousColor = b.write(hist.previousColor, rg::Access::CopyDest);
        hist.previousGuides = b.write(hist.previousGuides, rg::Access::CopyDest);
        const rg::RgTexture to[] = {hist.previousColor, hist.previousGuides};
        const rhi::TextureRegion region = rhi::TextureRegion().setSize(filterPoolWidth(), growth.rows * 8);
        return [=](rg::PassContext& ctx) {
            for (int i = 0; i < 2; ++i) ctx.cmd().copyTexture(ctx.texture(to[i]), region, ctx.texture(from[i]), region);
        };
    });
}

// caustics.filterTiles: this frame's tile state (shaders/tiles.h) and the list's indirect arguments set to
// (0, 1, 1, 0), then caustics.filterTiles.list lists the tiles and gives each a pool tile. Nothing after it runs
// on an unlisted tile.
FilterTiles addTilePasses(rg::RenderGraph& graph, CausticFrame& f, HistoryHandles& hist, rg::RgTexture raw,
                          bool historyUsable, const FilterInputLayout& layout) {
    const uint32_t w = f.width, h = f.height, tilesX = (w + 7) / 8, tilesY = (h + 7) / 8;
    const uint32_t capacity = f.history->poolTiles;
    FilterTiles t;
    graph.addPass(filterPassName(f, "caustics.filterTiles"), [&](rg::PassBuilder& b) {
        b.setStages(rhi::PipelineStages::Compute);
        f.camera = b.read(f.camera, rg::Access::ConstantBuffer);
        const GBuffer& g = f.in->gbuffer;
        const rg::RgTexture in[] = {b.read(raw), b.read(g.linearDepth), b.read(g.objectId), b.read(hist.previousTiles),
                                    b.read(layout.index)};
        hist.tiles = b.write(hist.tiles);
        t.args = b.write(b.createBuffer("caustics.filterTileArgs",
                                        rhi::BufferDesc().setByteSize(16)
                                            .setUsage(rhi::BufferUsage::Storage | rhi::BufferUsage::Indirect | rhi::BufferUsage::CopySource)
                                            .setDebugName("caustics.filterTileArgs")));
        CausticFrame fr = f;
        rg::RgTexture o = hist.tiles;
        rg::RgBuffer args = t.args;
        const shader::FilterTilesParams push{historyUsable ? 1u : 0u, f.in->settings.filterMaxHistory};
        const bool listOrder = layout.listOrder;
        return [=](rg::PassContext& ctx) {
            auto d = PassBindingSet(shader_bindings::kCausticFilterTilesBindings, 0)
                         .buffer("camera", ctx.buffer(fr.camera))
                         .texture("current", ctx.texture(in[0]))
                         .texture("gLinearDepth", ctx.texture(in[1]))
                         .texture("gObjectId", ctx.texture(in[2]))
                         .texture("previousTiles", ctx.texture(in[3]))
                         .texture("tileState", ctx.texture(o))
                         .buffer("tileArgs", ctx.buffer(args))
                         .texture("specularIndex", ctx.texture(in[4]))
                         .desc();
            if (!d) log(LogLevel::Error, "caustics.filterTiles: " + d.message());
            else if (bindFilter(ctx, *fr.res, listOrder ? fr.res->filter.tilesList : fr.res->filter.tiles,
                                fr.res->filter.tilesLayout, std::move(*d), push))
                ctx.cmd().dispatch(tilesX, tilesY);   // one group per tile
        };
    });
    graph.addPass(filterPassName(f, "caustics.filterTiles.list"), [&](rg::PassBuilder& b) {
        b.setStages(rhi::PipelineStages::Compute);
        hist.tiles = b.write(hist.tiles, rg::Access::StorageReadWrite);
        hist.slots = b.write(hist.slots);
        t.args = b.write(t.args, rg::Access::StorageReadWrite);
        t.list = b.write(b.createBuffer("caustics.filterTileList", rhi::BufferDesc().setByteSize(uint64_t(capacity) * 4)
                                                                      .setUsage(rhi::BufferUsage::Storage)
                                                                      .setDebugName("caustics.filterTileList")));
        t.slots = hist.slots;
        CausticFrame fr = f;
        FilterTiles o = t;
        rg::RgTexture state = hist.tiles;
        const shader::TileListParams push{int32_t(tilesX), int32_t(tilesY), capacity};
        return [=](rg::PassContext& ctx) {
            auto d = PassBindingSet(shader_bindings::kCausticTileListBindings, 0)
                         .texture("tileState", ctx.texture(state))
                         .buffer("tileArgs", ctx.buffer(o.args))
                         .buffer("tiles", ctx.buffer(o.list))
                         .texture("slotMap", ctx.texture(o.slots))
                         .desc();
            if (!d) log(LogLevel::Error, "caustics.filterTiles.list: " + d.message());
            else dispatchImage(ctx, *fr.res, fr.res->filter.tileList, fr.res->filter.tileListLayout, std::move(*d), push, tilesX, tilesY);
        };
    });
    graph.addPass(filterPassName(f, "caustics.filterTiles.count"), [&](rg::PassBuilder& b) {
        t.args = b.read(t.args, rg::Access::CopySource);
        b.setSideEffects();   // writes a host-visible buffer the graph does not track
        rg::RgBuffer args = t.args;
        CausticViewHistory* history = f.history;
        const uint32_t slot = f.res->frameSlot;
        return [=](rg::PassContext& ctx) {
            if (slot >= history->tileCounts.size() || !history->tileCounts[slot]) return;
            ctx.cmd().copyBuffer(history->tileCounts[slot], 0, ctx.buffer(args), 12, 4);
            history->tileCountRecorded[slot] = 1;
        };
    });
    // The next frame reads the tile state and the slot map: never culled.
    graph.markOutput(hist.tiles);
    graph.markOutput(hist.slots);
    return t;
}

}  // namespace caustics::filter
