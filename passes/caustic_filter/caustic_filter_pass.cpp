// caustics.resolve (radiance buffers -> textures) and the caustic filter (paper 3.4, built as SVGF,
// Schied et al. 2017; docs/caustics.md "Filter"), every filter pass dispatched indirectly over a list of
// the 8x8 tiles that received photons or still hold history (docs/caustics.md "Tiles"), each listed tile
// owning one tile of the filter's pool images (docs/caustics.md "Memory": the filter's memory follows
// the caustics' coverage, not the screen; its values are pre-exposed half precision):
//   caustics.filterHistoryGrow  after the pool grew: last frame's history into the grown pool
//   caustics.filterTiles  the view's tile state, the tile list and slot map (filter_tile_passes.cpp)
//   caustics.temporal   reprojected history, disocclusion tests, 1/n average up to the history cap; writes
//                       this frame's copy of the ping-ponged history (the result, unfiltered, its
//                       luminance deviation, the guides) and the a-trous guide, packed once per frame
//   caustics.variance   luminance variance: temporal moments, or photon shot noise for short histories
//   caustics.atrous.N   edge-aware a-trous iterations stopping at depth, normal, object and luminance,
//                       energy-preserving: the symmetric pair weights and their sums (.pairs, into
//                       one of two alternating regions of caustics.atrous.sums, zeroed by
//                       caustics.variance or the iteration before), then the shares
//   caustics.filterOutput  (atrousIterations 0 only) the temporal result into caustics.radiance
// The last pass writes into caustics.radiance, over the listed tiles (the others hold this frame's zeros).
// With settings.filter off the combined radiance is returned unfiltered. The second type filtered apart
// runs every pass again with ".secondType" after its name, then caustics.filterCombine.
#include <string>

#include "caustic_filter/atrous_bindings.h"
#include "caustic_filter/filter_graph.h"
#include "caustic_filter/shaders/atrous.h"
#include "caustic_filter/output_bindings.h"
#include "caustic_filter/resolve_bindings.h"
#include "caustic_filter/shaders/output.h"
#include "caustic_filter/shaders/resolve.h"
#include "caustic_filter/shaders/temporal.h"
#include "caustic_filter/temporal_bindings.h"
#include "caustic_filter/shaders/variance.h"
#include "caustic_filter/variance_bindings.h"
#include "caustic_filter/combine_types_bindings.h"
#include "caustic_filter/shaders/combine_types.h"
#include "caustics/rhi/log.h"
#include "common/specular_list.h"
#include "module/pass_bindings.h"

namespace caustics {
namespace {

using namespace filter;

// The resolve's push constants: fixed-point or float words, one buffer for both types or two.
shader::ResolveParams resolveParams(const CausticFrame& f, bool oneBuffer) {
    return {f.width, f.height,
            (f.res->floatAtomics ? 0u : shader::kResolveFixedPoint) | (oneBuffer ? shader::kResolveCombinedOnly : 0u) |
                (f.wideFixedPoint ? shader::kResolveWide : 0u),
            1.0f / f.fixedPointScale};
}

// Records the resolve shader: words `first` and `second` into the three image slots (push.width x
// push.height texels, one per word triple).
void recordResolve(rg::PassContext& ctx, const CausticFrame& f, const std::string& pass, rg::RgBuffer first,
                   rg::RgBuffer second, rg::RgTexture outFirst, rg::RgTexture outSecond, rg::RgTexture outCombined,
                   const shader::ResolveParams& push) {
    auto d = PassBindingSet(shader_bindings::kCausticResolveBindings, 0)
                 .buffer("firstWords", ctx.buffer(first))
                 .buffer("secondWords", ctx.buffer(second))
                 .texture("outFirst", ctx.texture(outFirst))
                 .texture("outSecond", ctx.texture(outSecond))
                 .texture("outCombined", ctx.texture(outCombined))
                 .desc();
    if (!d) log(LogLevel::Error, pass + ": " + d.message());
    else dispatchImage(ctx, *f.res, f.res->filter.resolve, f.res->filter.resolveLayout, std::move(*d), push, push.width, push.height);
}

void addResolvePass(rg::RenderGraph& graph, CausticFrame& f, CausticOutputs& out) {
    const uint32_t w = f.width, h = f.height;
    graph.addPass("caustics.resolve", [&](rg::PassBuilder& b) {
        b.setStages(rhi::PipelineStages::Compute);
        // One buffer for both types (CausticFrameInputs::separateTypes off): it is bound twice and the
        // radiance texture in all three image slots; the shader writes only the sum.
        const bool separate = f.separateTypes;
        f.radiance1 = b.read(f.radiance1, rg::Access::SampledRead);
        if (separate) {
            f.radiance2 = b.read(f.radiance2, rg::Access::SampledRead);
            out.firstType = b.write(b.createTexture("caustics.firstType", screenImageDesc(w, h, "caustics.firstType")));
            out.secondType = b.write(b.createTexture("caustics.secondType", screenImageDesc(w, h, "caustics.secondType")));
        }
        out.radiance = b.write(b.createTexture("caustics.radiance", screenImageDesc(w, h, "caustics.radiance")));
        CausticFrame fr = f;
        CausticOutputs o = out;
        const shader::ResolveParams push = resolveParams(f, !separate);
        return [=](rg::PassContext& ctx) {
            recordResolve(ctx, fr, "caustics.resolve", fr.radiance1, separate ? fr.radiance2 : fr.radiance1,
                          separate ? o.firstType : o.radiance, separate ? o.secondType : o.radiance, o.radiance, push);
        };
    });
}

// One type's buffer into a new texture `name` (the shader's one-buffer mode: the buffer bound twice, the
// texture in all three image slots): the types filtered apart resolve each just before its filter run,
// so the two buffers, the two textures and the second type's guides are never all alive at once
// (docs/caustics.md "Second-type guides", memory). listOrder: the buffer and the texture hold one texel
// per list entry (common/specular_list.h), the texture kSpecularListRow x f.listRows.
void addOneTypeResolvePass(rg::RenderGraph& graph, CausticFrame& f, const std::string& pass, rg::RgBuffer& words,
                           rg::RgTexture& target, const std::string& name, bool listOrder) {
    graph.addPass(pass, [&](rg::PassBuilder& b) {
        b.setStages(rhi::PipelineStages::Compute);
        words = b.read(words, rg::Access::SampledRead);
        const uint32_t w = listOrder ? shader::kSpecularListRow : f.width, h = listOrder ? f.listRows : f.height;
        target = b.write(b.createTexture(name, screenImageDesc(w, h, name.c_str())));
        CausticFrame fr = f;
        const rg::RgBuffer in = words;
        const rg::RgTexture o = target;
        shader::ResolveParams push = resolveParams(f, true);
        push.width = w;
        push.height = h;
        return [=](rg::PassContext& ctx) { recordResolve(ctx, fr, pass, in, in, o, o, o, push); };
    });
}

// This frame's filter inputs that every pass after caustics.temporal reads.
struct FilterFrame {
    FilterInputLayout layout;   // where the frame inputs hold a pixel (filter_graph.h)
    FilterTiles tiles;
    rg::RgTexture guide;   // pool RGBA32UI: the a-trous guide (caustics.temporal, filterPackAtrousGuide)
    uint32_t poolTiles = 0;
    float preExposure = 1.0f;
};

// Iteration i (step 2^i) on `radiance` (pool: rgb, a deviation), which it replaces with its result; the
// last iteration writes into `output` (caustics.radiance) instead. Two passes: each pixel's pair weights to
// its 12 later neighbours, added to both pixels' weight sums in the iteration's region of `sums`
// (caustics.variance zeroes the first), then the shares w / W_q, which zero the next iteration's region
// (passes/caustic_filter/shaders/atrous.h; docs/caustics.md "Cost").
void addAtrousIteration(rg::RenderGraph& graph, CausticFrame& f, uint32_t i, FilterFrame& ff, rg::RgTexture& radiance,
                        rg::RgTexture& output, rg::RgBuffer& sums, bool jitteredGuides) {
    const CausticsSettings& s = f.in->settings;
    const bool last = i + 1 == s.atrousIterations;
    const std::string name = "caustics.atrous." + std::to_string(i);
    const uint32_t region = ff.poolTiles * shader::kFilterGroupThreads;
    const shader::AtrousParams push{int32_t(1) << i, int32_t(f.width), int32_t(f.height), s.filterLuminanceSigma,
                                    1.0f / ff.preExposure, jitteredGuides ? 1.0f : 0.0f, (i & 1u) * region,
                                    last ? shader::kAtrousNoNextSums : ((i + 1) & 1u) * region};
    const bool listOrder = ff.layout.listOrder;
    rg::RgTexture pairs;
    graph.addPass(filterPassName(f, name + ".pairs"), [&](rg::PassBuilder& b) {
        b.setStages(rhi::PipelineStages::Compute);
        const rg::RgTexture in = b.read(radiance), guide = b.read(ff.guide);
        readTiles(b, ff.tiles, true);
        pairs = b.write(b.createTexture(name + ".pairs", poolImageDesc(ff.poolTiles, rhi::Format::RGBA32_UINT, "caustics.atrousPairs")));
        sums = b.write(sums, rg::Access::StorageReadWrite);
        CausticFrame fr = f;
        rg::RgTexture o = pairs;
        rg::RgBuffer w = sums;
        FilterTiles t = ff.tiles;
        return [=](rg::PassContext& ctx) {
            dispatchDeclared(ctx, *fr.res, fr.res->filter.atrousPairs, fr.res->filter.atrousPairsLayout,
                             PassBindingSet(shader_bindings::kCausticAtrousPairsBindings, 0)
                                 .texture("inColor", ctx.texture(in))
                                 .texture("guides", ctx.texture(guide))
                                 .texture("slotMap", ctx.texture(t.slots))
                                 .buffer("tiles", ctx.buffer(t.list))
                                 .texture("outPairs", ctx.texture(o))
                                 .buffer("weightSums", ctx.buffer(w)),
                             push, t.args);
        };
    });
    graph.addPass(filterPassName(f, name), [&](rg::PassBuilder& b) {
        b.setStages(rhi::PipelineStages::Compute);
        const rg::RgTexture in = b.read(radiance), pw = b.read(pairs), index = b.read(ff.layout.index);
        const rg::RgBuffer w = sums = last ? b.read(sums) : b.write(sums, rg::Access::StorageReadWrite);
        readTiles(b, ff.tiles, true);
        if (last) radiance = output = b.write(output);
        else radiance = b.write(b.createTexture(name, poolImageDesc(ff.poolTiles, rhi::Format::RGBA16_FLOAT, "caustics.atrous")));
        CausticFrame fr = f;
        rg::RgTexture o = radiance;
        FilterTiles t = ff.tiles;
        return [=](rg::PassContext& ctx) {
            const auto& declared = last ? shader_bindings::kCausticAtrousLastBindings : shader_bindings::kCausticAtrousBindings;
            PassBindingSet set(declared, 0);
            set.texture("inColor", ctx.texture(in))
                .texture("slotMap", ctx.texture(t.slots))
                .buffer("tiles", ctx.buffer(t.list))
                .buffer("weightSums", ctx.buffer(w))
                .texture("pairs", ctx.texture(pw))
                .texture("outColor", ctx.texture(o));
            if (last) set.texture("specularIndex", ctx.texture(index));
            const rhi::ComputePipelineHandle& lastPipeline = listOrder ? fr.res->filter.atrousLastList : fr.res->filter.atrousLast;
            dispatchDeclared(ctx, *fr.res, last ? lastPipeline : fr.res->filter.atrous,
                             last ? fr.res->filter.atrousLastLayout : fr.res->filter.atrousLayout, set, push, t.args);
        };
    });
}

// Where the temporal pass confirms a rise before it drops a history (shaders/temporal.h, temporalVerdict):
// where the run holds the second type, whose photons each lie in several pixels' gather disks.
uint32_t temporalConfirmRises(const CausticFrame& f, bool secondTypeRun) {
    if (secondTypeRun) return shader::kTemporalConfirmEvery;
    const bool merged = !f.separateTypes && f.specularIndex.valid();   // the second type ran, into the same radiance
    return merged && f.in->gbuffer.optics.valid() ? shader::kTemporalConfirmSpecular : shader::kTemporalConfirmNone;
}

// caustics.temporal: last frame's history reprojected into this frame's (ping-pong, no copy).
// motionGuides: f's G-buffer is the second type's guides (docs/caustics.md "Second-type guides").
void addTemporalPass(rg::RenderGraph& graph, CausticFrame& f, HistoryHandles& hist, FilterFrame& ff, rg::RgTexture raw,
                     bool historyUsable, uint32_t readCopy, bool motionGuides) {
    const GBuffer& g = f.in->gbuffer;
    const uint32_t next = readCopy ^ 1u, frameIndex = f.in->frameIndex;
    graph.addPass(filterPassName(f, "caustics.temporal"), [&](rg::PassBuilder& b) {
        b.setStages(rhi::PipelineStages::Compute);
        f.camera = b.read(f.camera, rg::Access::ConstantBuffer);
        const uint32_t confirmRises = temporalConfirmRises(f, motionGuides);
        // The camera G-buffer's optics only where the pass tells the glass's pixels by it: another read
        // would keep the G-buffer's optics alive up to here (the frame's peak, docs/caustics.md "Memory").
        const rg::RgTexture in[] = {b.read(raw), b.read(g.linearDepth), b.read(g.normalRoughness), b.read(g.objectId),
                                    b.read(hist.previousColor), b.read(hist.previousGuides), b.read(hist.previousSlots),
                                    b.read(ff.layout.index),
                                    confirmRises == shader::kTemporalConfirmSpecular ? b.read(g.optics) : g.normalRoughness};
        readTiles(b, ff.tiles, false);
        hist.color = b.write(hist.color);
        hist.guides = b.write(hist.guides);
        ff.guide = b.write(b.createTexture("caustics.filterGuide", poolImageDesc(ff.poolTiles, rhi::Format::RGBA32_UINT,
                                                                                 "caustics.filterGuide")));
        CausticFrame fr = f;
        HistoryHandles o = hist;
        FilterTiles t = ff.tiles;
        rg::RgTexture guide = ff.guide;
        const float pre = ff.preExposure;
        const shader::TemporalParams built{historyUsable ? 1u : 0u, float(f.in->settings.filterMaxHistory), pre, 1.0f,
                                             motionGuides ? 1u : 0u, f.casterMotion && !motionGuides ? 1u : 0u,
                                             f.objectMotion && !motionGuides ? 1u : 0u, f.plan.instanceCount,
                                             confirmRises};
        const bool listOrder = ff.layout.listOrder;
        f.casterMotionWords = b.read(f.casterMotionWords, rg::Access::SampledRead);
        f.instanceMotionRows = b.read(f.instanceMotionRows, rg::Access::SampledRead);
        const rg::RgBuffer casterMotion = f.casterMotionWords, instanceRows = f.instanceMotionRows;
        return [=](rg::PassContext& ctx) {
            // Only if the last EXECUTED frame wrote the copy this one reads (a dropped graph breaks it),
            // with the pre-exposure that frame stored it with.
            auto push = built;
            push.historyValid &= (fr.history->valid && fr.history->parity == readCopy) ? 1u : 0u;
            push.historyScale = pre / fr.history->preExposure[readCopy];
            const bool recorded = dispatchDeclared(ctx, *fr.res, listOrder ? fr.res->filter.temporalList : fr.res->filter.temporal,
                                                   fr.res->filter.temporalLayout,
                                                   PassBindingSet(shader_bindings::kCausticTemporalBindings, 0)
                                                       .buffer("camera", ctx.buffer(fr.camera))
                                                       .texture("current", ctx.texture(in[0]))
                                                       .texture("gLinearDepth", ctx.texture(in[1]))
                                                       .texture("gNormal", ctx.texture(in[2]))
                                                       .texture("gObjectId", ctx.texture(in[3]))
                                                       .texture("historyColor", ctx.texture(in[4]))
                                                       .texture("historyGuides", ctx.texture(in[5]))
                                                       .texture("previousSlots", ctx.texture(in[6]))
                                                       .buffer("tiles", ctx.buffer(t.list))
                                                       .texture("outColor", ctx.texture(o.color))
                                                       .texture("outGuides", ctx.texture(o.guides))
                                                       .texture("outFilterGuide", ctx.texture(guide))
                                                       .buffer("casterMotion", ctx.buffer(casterMotion))
                                                       .buffer("instanceMotion", ctx.buffer(instanceRows))
                                                       .texture("specularIndex", ctx.texture(in[7]))
                                                       .texture("gOptics", ctx.texture(in[8])),
                                                   push, t.args);
            if (recorded) {
                // Committed when recorded, not when the graph was built: this frame's copy is the next
                // frame's previous one.
                fr.history->valid = true;
                fr.history->preExposure[next] = pre;
                fr.history->parity = next;
                fr.history->lastExecutedFrame = frameIndex;
            }
        };
    });
    // The next frame reads the history: never culled.
    graph.markOutput(hist.color);
    graph.markOutput(hist.guides);
}

// The filter over `raw` (in place: its last pass writes the result into it over the listed tiles),
// guided by f's G-buffer, with f's history; returns the tile list's arguments.
rg::RgBuffer addFilterChain(rg::RenderGraph& graph, CausticFrame& f, rg::RgTexture& raw, bool motionGuides) {
    const CausticsSettings& s = f.in->settings;
    const uint32_t w = f.width, h = f.height;
    const GBuffer& g = f.in->gbuffer;
    // The view's history (caustic_passes.h): valid only after an executed frame of this view. A
    // previous build that never executed is undone first when it is superseded (this build is for the
    // same or an earlier frame), or when it was for a frame before the last executed one and this build
    // is for a later one: a graph a host built for sizing with a stale frame number and dropped (a build
    // ahead is for a later frame than the last executed; a count restarted with resetHistory stays below
    // it until it passes it).
    CausticViewHistory& vh = *f.history;
    const uint32_t frameIndex = f.in->frameIndex;
    const bool stale = vh.lastExecutedFrame && vh.lastBuiltFrame && *vh.lastBuiltFrame < *vh.lastExecutedFrame &&
                       frameIndex > *vh.lastExecutedFrame;
    const bool dropped = vh.lastBuiltFrame && vh.lastBuiltFrame != vh.lastExecutedFrame &&
                         (frameIndex <= *vh.lastBuiltFrame || stale);
    if (dropped) {
        vh.builtParity = vh.parityBeforeLastBuild;
        vh.builtValid = vh.validBeforeLastBuild;
    }
    vh.parityBeforeLastBuild = vh.builtParity;
    vh.validBeforeLastBuild = vh.builtValid;
    vh.lastBuiltFrame = frameIndex;
    HistoryHandles hist = importHistory(graph, vh);
    const bool historyUsable = vh.builtValid && !f.in->resetHistory;
    // The next graph built reads what this one writes (caustic_passes.h, CausticViewHistory::builtParity).
    const uint32_t readCopy = vh.builtParity;
    addPoolGrowthPass(graph, f, hist, readCopy, historyUsable);
    vh.builtParity ^= 1u;
    vh.builtValid = true;
    // caustics.resolve's radiance: this frame's photons, zero in every tile the list leaves out.
    FilterFrame ff;
    ff.layout = filterInputLayout(f, motionGuides);
    ff.tiles = addTilePasses(graph, f, hist, raw, historyUsable, ff.layout);
    ff.poolTiles = f.history->poolTiles;
    ff.preExposure = filterPreExposure(f);
    addTemporalPass(graph, f, hist, ff, raw, historyUsable, readCopy, motionGuides);
    const rg::RgTexture color = hist.color, guides = hist.guides;

    if (s.atrousIterations == 0) {
        graph.addPass(filterPassName(f, "caustics.filterOutput"), [&](rg::PassBuilder& b) {
            b.setStages(rhi::PipelineStages::Compute);
            const rg::RgTexture in[] = {b.read(color), b.read(guides), b.read(ff.layout.index)};
            readTiles(b, ff.tiles, false);
            raw = b.write(raw, rg::Access::StorageReadWrite);
            CausticFrame fr = f;
            rg::RgTexture o = raw;
            FilterTiles t = ff.tiles;
            const shader::FilterOutputParams push{int32_t(w), int32_t(h), 1.0f / ff.preExposure};
            const bool listOrder = ff.layout.listOrder;
            return [=](rg::PassContext& ctx) {
                dispatchDeclared(ctx, *fr.res, listOrder ? fr.res->filter.outputList : fr.res->filter.output, fr.res->filter.outputLayout,
                                 PassBindingSet(shader_bindings::kCausticFilterOutputBindings, 0)
                                     .texture("temporalColor", ctx.texture(in[0]))
                                     .texture("temporalGuides", ctx.texture(in[1]))
                                     .buffer("tiles", ctx.buffer(t.list))
                                     .texture("radiance", ctx.texture(o))
                                     .texture("specularIndex", ctx.texture(in[2])),
                                 push, t.args);
            };
        });
        return ff.tiles.args;
    }
    rg::RgTexture radiance;
    rg::RgBuffer sums;
    graph.addPass(filterPassName(f, "caustics.variance"), [&](rg::PassBuilder& b) {
        b.setStages(rhi::PipelineStages::Compute);
        const rg::RgTexture in[] = {b.read(raw), b.read(color), b.read(guides), b.read(g.objectId), b.read(g.normalRoughness),
                                    b.read(ff.layout.index)};
        readTiles(b, ff.tiles, true);
        radiance = b.write(b.createTexture("caustics.variance", poolImageDesc(ff.poolTiles, rhi::Format::RGBA16_FLOAT,
                                                                              "caustics.variance")));
        // The a-trous weight sums W: two regions of a pool's texels that the iterations alternate between;
        // this pass zeroes the first iteration's, each shares pass the next one's (docs/caustics.md "Cost").
        const uint64_t regionBytes = uint64_t(ff.poolTiles) * shader::kFilterGroupThreads * 4;
        sums = b.write(b.createBuffer("caustics.atrous.sums", rhi::BufferDesc()
                                                                  .setByteSize((s.atrousIterations > 1 ? 2 : 1) * regionBytes)
                                                                  .setUsage(rhi::BufferUsage::Storage)
                                                                  .setDebugName("caustics.atrousSums")),
                       rg::Access::StorageReadWrite);
        CausticFrame fr = f;
        rg::RgTexture o = radiance;
        rg::RgBuffer zeroed = sums;
        FilterTiles t = ff.tiles;
        // The second type's guides carry each pixel's photon weight (second_type_guides.h).
        const shader::VarianceParams push{int32_t(w), int32_t(h), ff.preExposure, motionGuides ? 1u : 0u};
        const bool listOrder = ff.layout.listOrder;
        return [=](rg::PassContext& ctx) {
            dispatchDeclared(ctx, *fr.res, listOrder ? fr.res->filter.varianceList : fr.res->filter.variance, fr.res->filter.varianceLayout,
                             PassBindingSet(shader_bindings::kCausticVarianceBindings, 0)
                                 .texture("current", ctx.texture(in[0]))
                                 .texture("temporalColor", ctx.texture(in[1]))
                                 .texture("temporalGuides", ctx.texture(in[2]))
                                 .texture("gObjectId", ctx.texture(in[3]))
                                 .texture("gNormal", ctx.texture(in[4]))
                                 .texture("slotMap", ctx.texture(t.slots))
                                 .buffer("tiles", ctx.buffer(t.list))
                                 .texture("outColor", ctx.texture(o))
                                 .buffer("weightSums", ctx.buffer(zeroed))
                                 .texture("specularIndex", ctx.texture(in[5])),
                             push, t.args);
        };
    });
    for (uint32_t i = 0; i < s.atrousIterations; ++i) addAtrousIteration(graph, f, i, ff, radiance, raw, sums, motionGuides);
    return ff.tiles.args;
}

// caustics.filterCombine: caustics.radiance = both types, each filtered on its own guides. Without a
// first-type texture the radiance texture holds the filtered first type and gets the second added.
void addCombinePass(rg::RenderGraph& graph, CausticFrame& f, CausticOutputs& out) {
    graph.addPass("caustics.filterCombine", [&](rg::PassBuilder& b) {
        const bool firstTexture = out.firstType.valid();
        const rg::RgTexture second = b.read(out.secondType), first = firstTexture ? b.read(out.firstType) : second;
        // Through the index, one thread per pixel: a pass over the list would keep the list alive through
        // the first type's run, the frame's peak (docs/caustics.md "Second-type memory").
        const FilterInputLayout layout = filterInputLayout(f, true);
        const rg::RgTexture index = b.read(layout.index);
        out.radiance = b.write(out.radiance, firstTexture ? rg::Access::StorageWrite : rg::Access::StorageReadWrite);
        CausticFrame fr = f;
        rg::RgTexture o = out.radiance;
        const shader::CombineTypesParams push{{f.width, f.height}, firstTexture ? 0u : 1u, 0u};
        const bool listOrder = layout.listOrder;
        return [=](rg::PassContext& ctx) {
            auto desc = PassBindingSet(shader_bindings::kCombineTypesBindings, 0)
                            .texture("firstType", ctx.texture(first))
                            .texture("secondType", ctx.texture(second))
                            .texture("radiance", ctx.texture(o))
                            .texture("specularIndex", ctx.texture(index))
                            .desc();
            if (!desc) {
                log(LogLevel::Error, "caustics.filterCombine: " + desc.message());
                return;
            }
            dispatchImage(ctx, *fr.res, listOrder ? fr.res->filter.combineList : fr.res->filter.combine, fr.res->filter.combineLayout,
                          *desc, push, fr.width, fr.height);
        };
    });
}

// The second type's own run of the filter, on its guides (the receiver seen through the glass), with
// its own history, reprojected with the receiver's motion (docs/caustics.md "Second-type guides").
void addSecondTypeFilterChain(rg::RenderGraph& graph, CausticFrame& f, CausticOutputs& out) {
    const SecondTypeGuides& guides = f.secondTypeGuides;
    CausticFrameInputs receiver = *f.in;
    receiver.gbuffer.linearDepth = guides.depthMotion;
    receiver.gbuffer.normalRoughness = guides.normal;
    receiver.gbuffer.objectId = guides.objectId;
    CausticFrame secondFrame = f;
    secondFrame.in = &receiver;
    secondFrame.history = f.history->secondType.get();
    secondFrame.filterRun = ".secondType";
    addFilterChain(graph, secondFrame, out.secondType, true);
    f.camera = secondFrame.camera;
    f.casterMotionWords = secondFrame.casterMotionWords;
    f.instanceMotionRows = secondFrame.instanceMotionRows;
}

}  // namespace

void addResolveAndFilterPasses(rg::RenderGraph& graph, CausticFrame& f, CausticOutputs& out) {
    const CausticsSettings& s = f.in->settings;
    const bool secondTypeRan = s.secondType && !f.plan.maps.empty();
    // The first type lies on what the camera sees: its G-buffer. The second lies on the receiver seen
    // through the glass: filtered apart on that receiver's guides; then both are summed.
    const bool apart = s.filter && s.filterSecondTypeApart && secondTypeRan && f.history->secondType && f.separateTypes;
    if (apart && !f.in->separateTypes) {
        // No first-type texture (no host asked for it): the second type is resolved, guided and
        // filtered first, then the first type into caustics.radiance, filtered there in place, and
        // caustics.filterCombine adds the second. The guides come after the stored hits and the first
        // type's buffer is the only one left while they live (the frame's peak, docs/caustics.md).
        addOneTypeResolvePass(graph, f, "caustics.resolve.secondType", f.radiance2, out.secondType, "caustics.secondType",
                              f.secondTypeListOrder);
        addSecondTypeGuidePasses(graph, f);
        addSecondTypeFilterChain(graph, f, out);
        addOneTypeResolvePass(graph, f, "caustics.resolve", f.radiance1, out.radiance, "caustics.radiance", false);
        out.filterTiles = addFilterChain(graph, f, out.radiance, false);
        addCombinePass(graph, f, out);
        return;
    }
    addResolvePass(graph, f, out);
    // The second type's guides (culled unless the filter runs it apart or a host reads them), after the
    // resolve: by then the stored hits and the radiance buffers are gone.
    if (secondTypeRan) addSecondTypeGuidePasses(graph, f);
    if (!s.filter) return;
    if (!apart) {
        out.filterTiles = addFilterChain(graph, f, out.radiance, false);
        return;
    }
    // A host asked for the types' own textures (an AOV): each filtered in its texture, then summed.
    addSecondTypeFilterChain(graph, f, out);
    out.filterTiles = addFilterChain(graph, f, out.firstType, false);
    addCombinePass(graph, f, out);
}

}  // namespace caustics
