// addCausticPasses: plans the maps on the CPU, then adds the passes of caustic_passes.h in order.
#include <algorithm>
#include <cmath>
#include <string>
#include <cstdio>
#include <cstring>

#include <glm/gtc/packing.hpp>

#include "caustic_maps/caustic_internal.h"   // and caustic_filter/caustic_filter.h: the filter pool sizes
#include "caustics/sphere_capacity.h"
#include "common/caster_motion.h"
#include "common/octahedral.h"

namespace caustics {

void addSetupPass(rg::RenderGraph& graph, CausticFrame& f) {
    graph.addPass("caustics.setup", [&](rg::PassBuilder& b) {
        // RGB per pixel: float or uint32 words, or uint64 fixed-point words.
        const uint64_t pixelBytes = uint64_t(f.width) * f.height * (f.wideFixedPoint ? 24 : 12);
        auto buffer = [&](const char* name, uint64_t bytes, rhi::BufferUsage usage) {
            return b.write(b.createBuffer(name, rhi::BufferDesc().setByteSize(bytes).setUsage(usage).setDebugName(name)),
                           rg::Access::CopyDest);
        };
        const auto storage = rhi::BufferUsage::Storage | rhi::BufferUsage::CopyDest;
        f.camera = buffer("caustics.camera", sizeof(CameraConstants), rhi::BufferUsage::Constant | rhi::BufferUsage::CopyDest);
        f.maps = buffer("caustics.maps", std::max<size_t>(1, f.plan.maps.size()) * sizeof(CausticMapGpu), storage);
        f.radiance1 = buffer("caustics.firstTypeBuffer", pixelBytes, storage | rhi::BufferUsage::CopySource);
        // One accumulation buffer for both types unless the host asked to see them apart.
        // (In list order caustics.specularPixels creates it, one RGB per list entry.)
        if (f.separateTypes && !f.secondTypeListOrder)
            f.radiance2 = buffer("caustics.secondTypeBuffer", pixelBytes, storage | rhi::BufferUsage::CopySource);
        f.stats = buffer("caustics.stats", kStatCount * 4, storage | rhi::BufferUsage::CopySource);
        // The forward grid (launches, 1, 1), written by caustics.photonPlan.
        f.forwardArgs = buffer("caustics.forwardArgs", 12, storage | rhi::BufferUsage::Indirect);
        const uint32_t forwardGrid[3] = {0u, 1u, 1u};
        // Per layer: emitter counts (caustics.emitters) and photons per texel (caustics.photonPlan); the
        // instance -> layer ownership of every light with layers (caustic_map_plan.h).
        const size_t layers = f.plan.maps.size();
        if (layers > 0) {
            f.layerPlans = buffer("caustics.layerPlans", layers * sizeof(CausticLayerPlanGpu), storage | rhi::BufferUsage::CopySource);
            f.owners = buffer("caustics.layerOwners", std::max<size_t>(1, f.plan.instanceLayers.size()) * 4, storage);
        }
        std::vector<uint32_t> owners = f.plan.instanceLayers;
        // Caster motion (docs/caustics.md "Moving casters"): per-instance rows, and 4 words per pixel
        // (the displacement sums x, y, z in 1/kCasterMotionScale m, the photon count), imported from the
        // frame slot (addCausticPasses sized them).
        const std::vector<glm::vec4> motionRows = f.instanceMotion;
        f.instanceMotionRows = b.write(f.instanceMotionRows, rg::Access::CopyDest);
        f.casterMotionWords = b.write(f.casterMotionWords, rg::Access::CopyDest);
        // The backward grid (specular pixels, 1, 1), counted up by caustics.specularPixels.
        const bool secondType = f.in->settings.secondType && !f.plan.maps.empty();
        if (secondType) f.backwardArgs = buffer("caustics.backwardArgs", 12, storage | rhi::BufferUsage::Indirect);
        const uint32_t backwardGrid[3] = {0u, 1u, 1u};
        CameraConstants built = f.in->camera;
        std::shared_ptr<const CameraConstants> executed = f.in->executedCamera;
        std::vector<CausticMapGpu> maps = f.plan.maps;
        CausticFrame h = f;
        return [=](rg::PassContext& ctx) {
            rhi::ICommandList& cmd = ctx.cmd();
            const CameraConstants& camera = executed ? *executed : built;   // the reprojection as executed
            cmd.writeBuffer(ctx.buffer(h.camera), &camera, sizeof(camera));
            if (!maps.empty()) cmd.writeBuffer(ctx.buffer(h.maps), maps.data(), maps.size() * sizeof(CausticMapGpu));
            else cmd.fillBuffer(ctx.buffer(h.maps), 0);
            cmd.fillBuffer(ctx.buffer(h.radiance1), 0);
            if (h.separateTypes && !h.secondTypeListOrder) cmd.fillBuffer(ctx.buffer(h.radiance2), 0);
            // Every counter 0 and the fixed-point scale in the last slot (disjoint ranges: no write-after-write).
            const float scale = h.res->floatAtomics ? 0.0f : h.fixedPointScale;
            cmd.fillBuffer(ctx.buffer(h.stats), 0, 0, uint64_t(kStatFixedPointScale) * 4);
            cmd.writeBuffer(ctx.buffer(h.stats), &scale, 4, uint64_t(kStatFixedPointScale) * 4);
            cmd.writeBuffer(ctx.buffer(h.forwardArgs), forwardGrid, sizeof(forwardGrid));
            if (h.layerPlans.valid()) cmd.fillBuffer(ctx.buffer(h.layerPlans), 0);
            if (h.owners.valid()) {
                if (owners.empty()) cmd.fillBuffer(ctx.buffer(h.owners), 0);
                else cmd.writeBuffer(ctx.buffer(h.owners), owners.data(), owners.size() * 4);
            }
            if (secondType) cmd.writeBuffer(ctx.buffer(h.backwardArgs), backwardGrid, sizeof(backwardGrid));
            if (motionRows.empty()) cmd.fillBuffer(ctx.buffer(h.instanceMotionRows), 0);
            else cmd.writeBuffer(ctx.buffer(h.instanceMotionRows), motionRows.data(), motionRows.size() * 16);
            cmd.fillBuffer(ctx.buffer(h.casterMotionWords), 0);
        };
    });
}

// Upper bound of caustics.forward's launches: per layer, emitters x ceil(raysPerTexel) with at most
// mapResolution^2 emitters; with a budget N_k, emitters x ceil(N_k / emitters) < N_k + emitters.
uint64_t forwardLaunchBound(const CausticsSettings& s, const CausticMapPlan& plan) {
    const uint64_t texels = uint64_t(s.mapResolution) * s.mapResolution;
    uint64_t bound = 0;
    for (const CausticMapGpu& m : plan.maps)
        bound += m.photons > 0.0f ? uint64_t(std::ceil(double(m.photons))) + texels
                                  : texels * uint64_t(std::ceil(s.raysPerTexel));
    return std::max<uint64_t>(bound, texels * uint64_t(std::ceil(s.raysPerTexel)));
}

// Refuses settings the device cannot run, naming the setting, before anything is allocated.
// 2^30 is the smallest maxRayDispatchInvocationCount Vulkan allows and D3D12's DispatchRays limit;
// every sphere of the second type is one AABB of the sphere BLAS, so the first sphere allocation
// (caustics/sphere_capacity.h) must fit maxPrimitiveCount (growth stops at it).
Status checkDeviceLimits(const CausticFrameInputs& in, const CausticMapPlan& plan, uint32_t firstSphereAllocation) {
    constexpr uint64_t kMaxRayLaunches = 1ull << 30;
    const uint64_t launches = forwardLaunchBound(in.settings, plan);
    if (launches > kMaxRayLaunches)
        return makeError("addCausticPasses: mapResolution " + std::to_string(in.settings.mapResolution) +
                         " x raysPerTexel " + std::to_string(in.settings.raysPerTexel) + " (or photonsPerFrame " +
                         std::to_string(in.settings.photonsPerFrame) + ") over " + std::to_string(plan.maps.size()) +
                         " map layers = up to " + std::to_string(launches) +
                         " ray launches, over the 2^30 a dispatch may have; lower mapResolution, raysPerTexel or "
                         "photonsPerFrame");
    const uint64_t pixels = uint64_t(in.gbuffer.width) * in.gbuffer.height;
    const uint64_t slots = pixels > UINT32_MAX ? pixels : firstSphereAllocation;
    const uint64_t maxPrimitives = in.device ? in.device->capabilities().maxPrimitiveCount : 0;
    if (in.settings.secondType && maxPrimitives != 0 && slots > maxPrimitives)
        return makeError("addCausticPasses: secondType's first sphere allocation (the specular surfaces in view) at " +
                         std::to_string(in.gbuffer.width) + "x" + std::to_string(in.gbuffer.height) + " is " +
                         std::to_string(slots) + " spheres, over the device's maxPrimitiveCount " +
                         std::to_string(maxPrimitives) + "; lower the resolution or turn secondType off");
    return okStatus();
}

Result<CausticOutputs> addCausticPasses(rg::RenderGraph& graph, CausticResources& persistent,
                                        const CausticFrameInputs& in) {
    CausticResources::Impl* res = persistent.impl();
    if (!res) return makeError("addCausticPasses: CausticResources were not created");
    if (!in.scene || !in.gpuScene || !in.sceneBindings) return makeError("addCausticPasses: scene inputs missing");
    // The channels the caustic passes read (caustics/gbuffer.h, hostGBufferRequirements).
    const GBuffer& g = in.gbuffer;
    if (!g.linearDepth.valid() || !g.objectId.valid() || g.width == 0 || g.height == 0 ||
        (in.settings.secondType && !g.optics.valid()) || (in.settings.filter && !g.normalRoughness.valid()))
        return makeError("addCausticPasses: the G-buffer lacks linearDepth, objectId, optics (secondType) or "
                         "normalRoughness (filter)");
    CAUSTICS_CHECK(in.settings.validate());
    const CausticView view = causticViewOf(in.camera);
    CausticPlanOptions planOptions;
    planOptions.drawOccluders = in.settings.mapOccluders;
    planOptions.view = &view;
    planOptions.receiverReach = in.settings.causticReceiverReach;
    planOptions.photons = in.photonsPerFrame ? *in.photonsPerFrame : in.settings.photonsPerFrame;
    const SpecularBounds bounds = computeSpecularBounds(*in.scene);
    CausticMapPlan plan = planCausticMaps(*in.scene, bounds, planOptions);
    // What the camera sees of the specular surfaces sizes the second type's first allocation.
    const uint32_t pixels = in.gbuffer.width * in.gbuffer.height;
    const double specularCoverage = in.settings.secondType ? imageCoverageSum(view, bounds.instanceSpheres, bounds.instanceLo, bounds.instanceHi) : 0.0;
    const uint32_t firstSphereAllocation = initialSphereAllocation(pixels, specularCoverage);
    CAUSTICS_CHECK(checkDeviceLimits(in, plan, firstSphereAllocation));
    CAUSTICS_CHECK(res->ensureScenePipelines(in.sceneBindings->layout));
    const uint32_t slot = in.frameSlot.value_or(in.frameIndex % uint32_t(res->frameSets.size()));
    if (slot >= res->frameSets.size())
        return makeError("addCausticPasses: frame slot " + std::to_string(slot) + " is not below framesInFlight " +
                         std::to_string(res->frameSets.size()));
    res->frameSlot = slot;
    res->frameSets[res->frameSlot].clear();
    res->retiredSphereStructures[res->frameSlot].clear();
    res->retiredTextures[res->frameSlot].clear();
    if (in.settings.secondType) CAUSTICS_CHECK(res->ensureSizeResources(pixels, firstSphereAllocation, res->frameSlot));
    CausticViewHistory* history = in.history ? in.history : &res->ownHistory;
    if (in.settings.filter)
        CAUSTICS_CHECK(res->ensureHistory(*history, in.gbuffer.width, in.gbuffer.height, in.settings.filterPoolTiles));
    // The second type is filtered apart, on its own guides (docs/caustics.md "Second-type guides").
    const bool filterTypesApart = in.settings.filter && in.settings.secondType && in.settings.filterSecondTypeApart;
    if (filterTypesApart) {
        if (!history->secondType) {
            history->secondType = std::make_shared<CausticViewHistory>();
            history->secondType->viewId = history->viewId;
        }
        const uint32_t secondPool = in.settings.filterPoolTiles
                                        ? in.settings.filterPoolTiles
                                        : initialSecondTypePoolTiles(in.gbuffer.width, in.gbuffer.height, specularCoverage);
        CAUSTICS_CHECK(res->ensureHistory(*history->secondType, in.gbuffer.width, in.gbuffer.height, secondPool));
    }

    CausticFrame f;
    f.in = &in;
    f.res = res;
    f.history = history;
    f.width = in.gbuffer.width;
    f.height = in.gbuffer.height;
    f.separateTypes = in.separateTypes || filterTypesApart;
    // Apart without an AOV that shows the second type alone: its images follow the specular pixels.
    f.secondTypeListOrder = filterTypesApart && !in.separateTypes && !plan.maps.empty();
    f.wideFixedPoint = !res->floatAtomics && res->int64Atomics;
    f.fixedPointScale = fixedPointScale(f.wideFixedPoint, in.settings.exposure * in.scene->exposure);
    f.plan = std::move(plan);
    // Taken every frame (the next frame compares with it), used only by the filter's history.
    InstanceMotion motion = instanceMotion(res->casterMotion, *in.scene, in.frameIndex);
    const bool motionUsable = in.settings.filter && in.settings.filterCasterMotion && !motion.rows.empty() &&
                              motion.rows.size() == shader::kCasterMotionRowsPerInstance * size_t(f.plan.instanceCount);
    f.objectMotion = motionUsable;
    f.casterMotion = motionUsable && motion.casterMoved;
    f.instanceMotion = motionUsable ? std::move(motion.rows) : std::vector<glm::vec4>();

    // The slot's motion buffers: 16 bytes (bound, unread) unless an instance (rows) or a caster (words) moved.
    const uint64_t motionWordBytes = f.casterMotion ? uint64_t(f.width) * f.height * 4 * shader::kCasterMotionWords : 16;
    CAUSTICS_CHECK(res->ensureCasterMotion(slot, f.objectMotion ? f.instanceMotion.size() * 16 : 16, motionWordBytes));
    f.instanceMotionRows = graph.importBuffer("caustics.instanceMotion", res->casterMotionRowBuffers[slot],
                                              rhi::ResourceState::Common, rhi::ResourceState::Common);
    f.casterMotionWords = graph.importBuffer("caustics.casterMotion", res->casterMotionWordBuffers[slot],
                                             rhi::ResourceState::Common, rhi::ResourceState::Common);

    CausticOutputs out;
    out.floatAtomics = res->floatAtomics;
    out.wideFixedPoint = f.wideFixedPoint;
    out.fixedPointScale = res->floatAtomics ? 0.0f : f.fixedPointScale;
    addSetupPass(graph, f);
    if (!f.plan.maps.empty()) {
        addMapPass(graph, f);
        addEmitterPass(graph, f);
        addPhotonPlanPass(graph, f);
        addForwardPass(graph, f);
        if (in.settings.secondType) addBackwardPasses(graph, f);
    }
    addResolveAndFilterPasses(graph, f, out);
    out.firstTypeBuffer = f.radiance1;
    out.secondTypeBuffer = f.radiance2;
    if (in.settings.secondType) out.hits = f.hits;   // else a placeholder the forward pass stored nothing in
    out.stats = f.stats;
    out.layerPlans = f.layerPlans;
    out.spheres = f.spheres;
    out.secondTypeGuides = f.secondTypeGuides;
    out.secondTypeListOrder = f.secondTypeListOrder;
    if (f.secondTypeListOrder) out.specularPixels = f.specularPixels;
    out.mapObjectIds = f.mapIds;
    out.plan = std::move(f.plan);
    return out;
}

glm::vec3 causticHitNormal(const CausticHit& hit) { return shader::octDecode(glm::unpackSnorm2x16(hit.normal)); }
glm::vec3 causticHitIncoming(const CausticHit& hit) { return shader::octDecode(glm::unpackSnorm2x16(hit.incoming)); }

float fixedPointScale(bool wideWords, float preExposure) {
    const float pre = std::isfinite(preExposure) && preExposure > 0.0f ? preExposure : 1.0f;
    return (wideWords ? kFixedPointScale64 : kFixedPointScale) * pre;
}

std::vector<std::string> causticStatsWarnings(std::span<const uint32_t> stats, const CausticsSettings& settings) {
    std::vector<std::string> warnings;
    if (stats.size() <= kStatStoredHitAttempts) return warnings;
    const uint32_t offered = stats[kStatStoredHitAttempts];
    if (settings.secondType && offered > settings.maxStoredHits)
        warnings.push_back("caustic hit buffer overflowed: " + std::to_string(offered) + " diffuse hits offered, " +
                           std::to_string(settings.maxStoredHits) + " kept (CausticsSettings::maxStoredHits); " +
                           "second-type caustics miss the rest");
    if (stats.size() > kStatAccumulationGiveUps && stats[kStatAccumulationGiveUps] > 0)
        warnings.push_back(std::to_string(stats[kStatAccumulationGiveUps]) +
                           " caustic radiance contributions were dropped: the float compare-and-swap loop gave up "
                           "under contention (D3D12 float path, docs/d3d12.md); the fixed-point path never drops");
    if (stats.size() > kStatFixedPointScale && stats[kStatSaturatedAdds] > 0) {
        float scale = 0.0f;
        std::memcpy(&scale, &stats[kStatFixedPointScale], 4);
        char limit[32];
        std::snprintf(limit, sizeof(limit), "%.3g", scale > 0.0f ? (scale > 1e10f ? 1.8e19 : 4.29e9) / scale : 0.0);
        warnings.push_back(std::to_string(stats[kStatSaturatedAdds]) +
                           " fixed-point caustic radiance adds saturated (pixels clipped at " + limit +
                           " cd/m^2 this frame): the pre-exposure (CausticsSettings::exposure x Scene::exposure) is "
                           "too high for this light; lower it (docs/caustics.md, \"Fixed point\")");
    }
    if (stats.size() > kStatSphereCapacity) {
        // The specular pixel list is cut at the capacity, so pixels past it get no sphere. A listed pixel's
        // launch appends up to kMaxSpheresPerPixel (its lobe branches): those past the capacity are
        // dropped and counted in kStatSpheresDropped. Pixels and spheres are told apart.
        const uint32_t specular = stats[kStatSpecularPixels], capacity = stats[kStatSphereCapacity];
        const uint32_t unlisted = specular > capacity ? specular - capacity : 0u, dropped = stats[kStatSpheresDropped];
        std::string lost;
        if (unlisted > 0)
            lost = std::to_string(unlisted) + " of " + std::to_string(specular) +
                   " specular pixels got no second-type sphere this frame";
        if (dropped > 0)
            lost += (lost.empty() ? "" : ", and ") + std::to_string(dropped) +
                    " second-type spheres of the others' lobe branches were dropped this frame";
        if (!lost.empty())
            warnings.push_back(lost + ", the sphere structures grow "
                               "next frame: they held " + std::to_string(capacity) +
                               " (sized from the specular pixel count of the last frame in the same "
                               "frame-in-flight slot, or the specular surfaces in view; docs/caustics.md, "
                               "\"Second-type cost\")");
    }
    return warnings;
}

Status prepareCausticPipelines(CausticResources& resources, const rhi::BindingLayoutHandle& sceneLayout) {
    CausticResources::Impl* r = resources.impl();
    if (!r) return makeError("prepareCausticPipelines: CausticResources were not created");
    return r->ensureScenePipelines(sceneLayout);
}

void releaseCausticView(CausticResources& resources, uint64_t viewId) {
    if (CausticResources::Impl* r = resources.impl()) r->sphereCounts.erase(viewId);
}

}  // namespace caustics
