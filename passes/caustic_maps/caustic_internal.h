#pragma once
// Internals shared by the caustic passes (not installed): the persistent objects and the per-frame
// graph handles that flow from one pass to the next.
#include <array>
#include <vector>

#include "caustic_filter/caustic_filter.h"
#include "caustics/caustic_passes.h"

namespace caustics {

// Push-constant bytes of the scene-trace passes (the Push structs of forward_trace_pass.cpp and
// backward_pass.cpp); their state objects are created with exactly these, which binding_truth_tests
// compare with the shaders' push blocks.
inline constexpr uint32_t kForwardPushBytes = 32, kBackwardPushBytes = 48;

struct CausticResources::Impl {
    rhi::IDevice* device = nullptr;
    bool floatAtomics = true;
    rhi::BindingLayoutHandle mapLayout, emitterLayout, forwardLayout, backwardLayout, gatherLayout;
    // Built against a scene binding layout (recreated when the scene's layout changes).
    const rhi::IBindingLayout* sceneLayoutSeen = nullptr;
    rhi::GraphicsPipelineHandle mapPipeline;
    rhi::ComputePipelineHandle emitterPipeline;   // scene set + emitterLayout
    rhi::BindingLayoutHandle gridLayout;
    rhi::ComputePipelineHandle gridFromCount;     // caustic_grid_pass.cpp
    rhi::StateObjectHandle forwardState, backwardState, gatherState;
    rhi::ShaderTableHandle forwardTable, backwardTable, gatherTable;
    CausticFilterPipelines filter;   // resolve + filter (caustic_filter/)
    rhi::BufferHandle sphereAabb;
    rhi::AccelStructHandle sphereBlas;
    rhi::AccelStructHandle sphereTlas;
    uint32_t tlasCapacity = 0;
    CausticViewHistory ownHistory;   // used when CausticFrameInputs::history is null
    // Binding sets made while recording must outlive the GPU's use: kept for framesInFlight frames.
    std::vector<std::vector<rhi::BindingSetHandle>> frameSets;
    uint32_t frameSlot = 0;

    Status ensureScenePipelines(const rhi::BindingLayoutHandle& sceneLayout);
    Status ensureSizeResources(uint32_t width, uint32_t height);
    Status ensureHistory(CausticViewHistory& history, uint32_t width, uint32_t height);
    // Binding set for this frame (kept alive); null after logging the error.
    rhi::BindingSetHandle makeSet(rhi::IDevice& device, const rhi::BindingLayoutHandle& layout,
                                  rhi::BindingSetDesc desc);
};

// Handles of one frame, filled pass by pass.
struct CausticFrame {
    const CausticFrameInputs* in = nullptr;
    CausticResources::Impl* res = nullptr;
    CausticViewHistory* history = nullptr;   // the view's (or res->ownHistory)
    uint32_t width = 0, height = 0;
    rg::RgBuffer camera, maps, radiance1, radiance2, hits, stats, spheres, instances;
    rg::RgBuffer emitters, forwardArgs;   // caustics.emitters -> caustics.forward
    rg::RgTexture mapIds, mapDepth;
    rg::RgAccelStruct sphereTlas;
    CausticMapPlan plan;
};

void addSetupPass(rg::RenderGraph& graph, CausticFrame& f);
void addMapPass(rg::RenderGraph& graph, CausticFrame& f);
void addEmitterPass(rg::RenderGraph& graph, CausticFrame& f);
// The grid (min(stats[statSlot], cap), 1, 1) of an indirect ray dispatch, in a new 12-byte buffer.
rg::RgBuffer addGridFromCountPass(rg::RenderGraph& graph, CausticFrame& f, const char* name, uint32_t statSlot,
                                  uint32_t cap);
void addForwardPass(rg::RenderGraph& graph, CausticFrame& f);
void addBackwardPasses(rg::RenderGraph& graph, CausticFrame& f);
void addResolveAndFilterPasses(rg::RenderGraph& graph, CausticFrame& f, CausticOutputs& out);

// Records one scene trace: the scene set (0), the pass's own set (1), push constants, the grid.
// The forward and backward passes differ only in these arguments.
template <typename PushConstants>
void bindSceneTrace(rhi::ICommandList& cmd, const rhi::StateObjectHandle& state, const rhi::ShaderTableHandle& table,
                    const rhi::BindingSetHandle& sceneSet, const rhi::BindingSetHandle& passSet,
                    const PushConstants& push) {
    cmd.setRayTracingState(state, table);
    cmd.setBindingSet(0, sceneSet);
    cmd.setBindingSet(1, passSet);
    cmd.setPushConstants(&push, sizeof(push));
}
template <typename PushConstants>
void recordSceneTrace(rhi::ICommandList& cmd, const rhi::StateObjectHandle& state, const rhi::ShaderTableHandle& table,
                      const rhi::BindingSetHandle& sceneSet, const rhi::BindingSetHandle& passSet,
                      const PushConstants& push, uint32_t width, uint32_t height, uint32_t depth) {
    bindSceneTrace(cmd, state, table, sceneSet, passSet, push);
    cmd.dispatchRays(width, height, depth);
}

}  // namespace caustics
