#pragma once
// Graph helpers shared by the caustic filter's passes (caustic_filter_pass.cpp, filter_tile_passes.cpp;
// docs/caustics.md "Filter", "Tiles", "Memory").
#include <string>
#include <string_view>
#include <utility>

#include "caustic_filter/caustic_filter.h"
#include "caustic_maps/caustic_internal.h"
#include "caustics/rhi/log.h"
#include "module/pass_bindings.h"

namespace caustics::filter {

// A filter pass's name in this run of the filter: `name`, then ".secondType" for the second type's own run
// (CausticFrame::filterRun), so that the bench times the two runs apart.
inline std::string filterPassName(const CausticFrame& f, std::string_view name) { return std::string(name) + f.filterRun; }

// A full-screen RGBA32F image (caustics.radiance and the separate types).
inline rhi::TextureDesc screenImageDesc(uint32_t w, uint32_t h, const char* name) {
    return rhi::TextureDesc().setSize(w, h).setFormat(rhi::Format::RGBA32_FLOAT)
        .setUsage(rhi::TextureUsage::Sampled | rhi::TextureUsage::Storage | rhi::TextureUsage::CopySource)
        .setDebugName(name);
}

// One of the filter's per-frame pool images: one 8x8 tile per listed tile (caustic_filter.h).
inline rhi::TextureDesc poolImageDesc(uint32_t poolTiles, rhi::Format format, const char* name) {
    return rhi::TextureDesc().setSize(filterPoolWidth(), filterPoolHeight(poolTiles)).setFormat(format)
        .setUsage(rhi::TextureUsage::Sampled | rhi::TextureUsage::Storage).setDebugName(name);
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

// One 8x8-group compute dispatch over a w x h grid.
template <typename Push>
bool dispatchImage(rg::PassContext& ctx, CausticResources::Impl& r, const rhi::ComputePipelineHandle& pipeline,
                   const rhi::BindingLayoutHandle& layout, rhi::BindingSetDesc bindings, const Push& push, uint32_t w,
                   uint32_t h) {
    if (!bindFilter(ctx, r, pipeline, layout, std::move(bindings), push)) return false;
    ctx.cmd().dispatch((w + 7) / 8, (h + 7) / 8);
    return true;
}

// One 8x8 group per listed tile, the group count read from the tile list's arguments.
template <typename Push>
bool dispatchTiles(rg::PassContext& ctx, CausticResources::Impl& r, const rhi::ComputePipelineHandle& pipeline,
                   const rhi::BindingLayoutHandle& layout, rhi::BindingSetDesc bindings, const Push& push,
                   rg::RgBuffer args) {
    if (!bindFilter(ctx, r, pipeline, layout, std::move(bindings), push)) return false;
    ctx.cmd().dispatchIndirect(ctx.buffer(args));
    return true;
}

// dispatchTiles with a set filled by name from the pass's one declaration (docs/shaders.md, "Bindings");
// a name or kind that does not match it is logged and nothing is dispatched.
template <typename Push>
bool dispatchDeclared(rg::PassContext& ctx, CausticResources::Impl& r, const rhi::ComputePipelineHandle& pipeline,
                      const rhi::BindingLayoutHandle& layout, const PassBindingSet& bindings, const Push& push,
                      rg::RgBuffer args) {
    auto desc = bindings.desc();
    if (!desc) {
        log(LogLevel::Error, "caustic filter: " + desc.message());
        return false;
    }
    return dispatchTiles(ctx, r, pipeline, layout, std::move(*desc), push, args);
}

// Where a filter run's frame inputs (the unfiltered radiance and the guides) hold a pixel
// (common/specular_list.h): at the pixel, or, for the second type's run when the frame keeps the second
// type in list order, at the pixel's list entry (the passes' *_list pipelines, caustic_filter.h). `index`
// is what the passes bind as specularIndex (the camera G-buffer's object ids, never read, when there is no
// list order).
struct FilterInputLayout {
    rg::RgTexture index;
    bool listOrder = false;
};
inline FilterInputLayout filterInputLayout(const CausticFrame& f, bool secondTypeRun) {
    if (secondTypeRun && f.secondTypeListOrder) return {f.specularIndex, true};
    return {f.specularIndex.valid() ? f.specularIndex : f.in->gbuffer.objectId, false};
}

// The view's ping-ponged history (caustic_passes.h): last frame's (read) and this frame's (written).
struct HistoryHandles {
    rg::RgTexture previousColor, previousGuides, previousTiles, previousSlots;
    rg::RgTexture color, guides, tiles, slots;
};
HistoryHandles importHistory(rg::RenderGraph& graph, const CausticViewHistory& history);
// caustics.filterHistoryGrow: after the pool grew (CausticViewHistory::growth), the copy this frame reads
// moves from the smaller pool's textures into hist's (a slot keeps its place); the old textures retire.
void addPoolGrowthPass(rg::RenderGraph& graph, CausticFrame& f, HistoryHandles& hist, uint32_t readCopy, bool historyUsable);

// The filter's tile list (caustics.filterTiles.list, shaders/tiles.h): `args` (listed tiles with a pool tile, 1, 1, tiles wanted)
// for the indirect dispatches, `list` the packed tiles (list index = pool tile), `slots` this frame's
// slot map.
struct FilterTiles {
    rg::RgBuffer args, list;
    rg::RgTexture slots;
};
// caustics.filterTiles, .clear, .list and .count (the read-back of the tiles wanted, which sizes the pool).
FilterTiles addTilePasses(rg::RenderGraph& graph, CausticFrame& f, HistoryHandles& hist, rg::RgTexture raw,
                          bool historyUsable, const FilterInputLayout& layout);

// The tile list bindings of a pass dispatched over it: the arguments (indirect), the list and, where
// it reads neighbours, the slot map.
inline void readTiles(rg::PassBuilder& b, FilterTiles& t, bool slots) {
    t.args = b.read(t.args, rg::Access::IndirectArgument);
    t.list = b.read(t.list);
    if (slots) t.slots = b.read(t.slots);
}

// The frame's pre-exposure (settings.exposure x scene.exposure, what the composite multiplies by): the
// pool's half-precision values are radiance times it, near 1 for white (docs/caustics.md "Memory").
float filterPreExposure(const CausticFrame& f);

}  // namespace caustics::filter
