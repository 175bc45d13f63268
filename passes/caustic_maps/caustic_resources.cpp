// Persistent objects of the caustic passes: binding layouts, pipelines and state objects (each pass's
// own from its folder: forward_pipeline.cpp, backward_pipeline.cpp, caustic_filter_resources.cpp), the
// sphere BLAS of the second-type gather, the sphere TLAS and the filter history.
#include "caustic_maps/caustic_internal.h"

#include "caustics/pass_shaders.h"
#include "caustics/sphere_capacity.h"
#include <algorithm>
#include <cstring>

#include "caustic_maps/caustic_map_bindings.h"
#include "caustic_maps/emitters_bindings.h"
#include "caustic_maps/grid_from_count_bindings.h"
#include "caustic_maps/photon_plan_bindings.h"
#include "caustic_maps/shaders/caustic_map.h"
#include "caustic_maps/shaders/emitters.h"
#include "caustic_maps/shaders/grid_from_count.h"
#include "caustic_maps/shaders/photon_plan.h"
#include "caustics/rhi/log.h"
#include "module/pass_bindings.h"

namespace caustics {

using rhi::ShaderStage;



CausticResources::CausticResources() = default;
CausticResources::~CausticResources() = default;
CausticResources::CausticResources(CausticResources&&) noexcept = default;
CausticResources& CausticResources::operator=(CausticResources&&) noexcept = default;

Result<CausticResources> CausticResources::create(rhi::IDevice& d, uint32_t framesInFlight) {
    if (framesInFlight < 1) return makeError("CausticResources::create: framesInFlight must be >= 1");
    CausticResources r;
    r.impl_ = std::make_unique<Impl>();
    Impl& m = *r.impl_;
    m.device = &d;
    m.frameSets.resize(framesInFlight);
    m.retiredSphereStructures.resize(framesInFlight);
    m.retiredTextures.resize(framesInFlight);
    m.floatAtomics = d.capabilities().shaderFloatAtomicAdd;
    m.int64Atomics = d.capabilities().shaderBufferInt64Atomics;
    CAUSTICS_TRY(m.mapLayout, createPassBindingLayout(d, shader_bindings::kCausticMapBindings, 1, ShaderStage::All));
    CAUSTICS_TRY(m.emitterLayout, createPassBindingLayout(d, shader_bindings::kEmittersBindings, 1, ShaderStage::All));
    CAUSTICS_CHECK(createForwardLayout(m));   // forward_trace/forward_pipeline.cpp
    CAUSTICS_TRY(m.photonPlanLayout, createPassBindingLayout(d, shader_bindings::kPhotonPlanBindings, 0, ShaderStage::All));
    CAUSTICS_TRY(m.photonPlanPipeline, createPassComputePipeline(d, "caustic_maps/photon_plan.comp", {m.photonPlanLayout},
                                               sizeof(shader::PhotonPlanParams)));
    CAUSTICS_TRY(m.gridLayout, createPassBindingLayout(d, shader_bindings::kGridFromCountBindings, 0, ShaderStage::All));
    CAUSTICS_TRY(m.gridFromCount, createPassComputePipeline(d, "caustic_maps/grid_from_count.comp", {m.gridLayout},
                                          sizeof(shader::GridFromCountParams)));
    CAUSTICS_TRY(m.filter, CausticFilterPipelines::create(d));

    CAUSTICS_CHECK(createBackwardPipelines(m));   // backward_trace/backward_pipeline.cpp

    // The top level over the spheres' bottom level: one instance, rebuilt after it every frame.
    rhi::AccelStructDesc tlas;
    tlas.isTopLevel = true;
    tlas.maxInstances = 1;
    tlas.flags = rhi::AccelBuildFlags::PreferFastBuild;
    tlas.debugName = "caustics.sphereTlas";
    CAUSTICS_TRY(m.sphereTlas, d.createAccelStruct(tlas));
    return r;
}

Status CausticResources::Impl::ensureScenePipelines(const rhi::BindingLayoutHandle& sceneLayout) {
    if (sceneLayoutSeen == sceneLayout.get() && mapPipeline) return okStatus();
    rhi::IDevice& d = *device;
    rhi::GraphicsPipelineDesc gp;
    CAUSTICS_TRY(gp.vertexShader.code, pass_shaders::shaderCode(d.backend(), "caustic_maps/caustic_map.vert"));
    gp.vertexShader.stage = ShaderStage::Vertex;
    CAUSTICS_TRY(gp.fragmentShader.code, pass_shaders::shaderCode(d.backend(), "caustic_maps/caustic_map.frag"));
    gp.fragmentShader.stage = ShaderStage::Fragment;
    gp.bindings.layouts = {sceneLayout, mapLayout};
    gp.bindings.pushConstantBytes = sizeof(shader::CausticMapParams);
    gp.cullMode = rhi::CullMode::None;   // glass is seen from both sides
    gp.colorFormats = {rhi::Format::R32_UINT};   // objectId only: the forward pass reads nothing else
    gp.depthFormat = rhi::Format::D32_FLOAT;
    gp.debugName = "caustics.maps";
    CAUSTICS_TRY(mapPipeline, d.createGraphicsPipeline(gp));
    CAUSTICS_TRY(emitterPipeline, createPassComputePipeline(d, "caustic_maps/emitters.comp", {sceneLayout, emitterLayout},
                                          sizeof(shader::EmittersParams)));
    CAUSTICS_CHECK(createForwardState(*this, sceneLayout));   // forward_trace/forward_pipeline.cpp
    CAUSTICS_CHECK(createBackwardState(*this, sceneLayout));   // backward_trace/backward_pipeline.cpp
    sceneLayoutSeen = sceneLayout.get();
    return okStatus();
}

Status CausticResources::Impl::ensureSizeResources(uint32_t pixels, uint32_t initialAllocation, uint32_t slot) {
    rhi::IDevice& d = *device;
    // Slots by the specular surfaces in view and the counts (caustics/sphere_capacity.h), not one per
    // pixel: 2.07 M slots at 1080p were the largest persistent allocation (docs/caustics.md, "Memory").
    const uint64_t maxPrimitives = d.capabilities().maxPrimitiveCount;
    uint32_t target = grownSphereAllocation(sphereSlots, sphereAllocationWanted, initialAllocation, sphereSlotLimit(pixels));
    if (maxPrimitives != 0) target = std::max<uint32_t>(sphereSlots, uint32_t(std::min<uint64_t>(target, maxPrimitives)));   // checkDeviceLimits
    sphereAllocationWanted = 0;
    if (sphereBlas && target <= sphereSlots) return okStatus();
    CAUSTICS_TRY(rhi::BufferHandle aabbs,
                 d.createBuffer(rhi::BufferDesc().setByteSize(uint64_t(std::max(target, 1u)) * kSphereAabbBytes)
                                    .setUsage(rhi::BufferUsage::Storage | rhi::BufferUsage::AccelStructInput | rhi::BufferUsage::CopyDest)
                                    .setDebugName("caustics.sphereAabbs")));
    rhi::AccelStructDesc blas;
    // NoDuplicateAnyHit: the any-hit shader accumulates (docs/caustics.md, "Second type").
    blas.geometries.push_back(rhi::GeometryDesc::fromAabbs({aabbs, 0, std::max(target, 1u), kSphereAabbBytes},
                                                           rhi::GeometryFlags::NoDuplicateAnyHit));
    blas.flags = rhi::AccelBuildFlags::PreferFastBuild;   // rebuilt every frame
    blas.debugName = "caustics.sphereBlas";
    CAUSTICS_TRY(rhi::AccelStructHandle grown, d.createAccelStruct(blas));
    if (sphereBlas) retiredSphereStructures[slot].push_back({std::move(sphereAabbs), std::move(sphereBlas)});
    sphereAabbs = std::move(aabbs);
    sphereBlas = std::move(grown);
    sphereSlots = target;
    return okStatus();
}

Status CausticResources::Impl::ensureHistory(CausticViewHistory& h, uint32_t width, uint32_t height,
                                             uint32_t requestedPoolTiles) {
    return ensureFilterHistory(*this, h, width, height, requestedPoolTiles);   // caustic_filter/filter_history.cpp
}

rhi::BindingSetHandle CausticResources::Impl::makeSet(rhi::IDevice& d, const rhi::BindingLayoutHandle& l,
                                                      rhi::BindingSetDesc desc) {
    auto set = d.createBindingSet(desc, l);
    if (!set) {
        log(LogLevel::Error, "caustics: binding set: " + set.message());
        return nullptr;
    }
    frameSets[frameSlot].push_back(set.value());
    return set.value();
}

rhi::BindingSetHandle CausticResources::Impl::makeSet(rhi::IDevice& d, const rhi::BindingLayoutHandle& l, const char* pass,
                                                      const PassBindingSet& bindings) {
    auto desc = bindings.desc();
    if (!desc) {
        log(LogLevel::Error, std::string(pass) + ": " + desc.message());
        return nullptr;
    }
    return makeSet(d, l, *desc);
}

}  // namespace caustics
