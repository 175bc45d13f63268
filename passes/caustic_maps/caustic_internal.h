#pragma once
// Internals shared by the caustic passes (not installed): the persistent objects and the per-frame
// graph handles that flow from one pass to the next.
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "caustic_filter/caustic_filter.h"
#include "bindings/shader_binding.h"
#include "caustics/caustic_passes.h"
#include "module/pass_bindings.h"

namespace caustics {

// Push-constant bytes of the forward pass (shader::ForwardParams, passes/forward_trace/shaders/forward.h);
// its state object is created with exactly these, which binding_truth_tests compare with the shader's
// push block.
inline constexpr uint32_t kForwardPushBytes = 32;

// One frame slot's read-back sphere count (kStatSpheres) of the last frame recorded in it, with the
// size of that frame; the host waited for that frame before executing a graph in the same slot.
struct SphereCountReadback {
    rhi::BufferHandle buffer;   // 8 bytes, Readback memory: the specular pixels, the spheres
    uint32_t width = 0, height = 0;
    bool recorded = false;      // a frame's copy into it was recorded
};

// One sphere's AABB in the sphere BLAS (min xyz, max xyz); slots past a frame's sphere count stay zero
// (backward_trace/specular_pixels_pass.cpp).
inline constexpr uint32_t kSphereAabbBytes = 24;

// The instance transforms of this frame and the one before (caster_motion.cpp; docs/caustics.md
// "Moving casters"): taken when a new frame number is built, so views of one frame share them.
struct CasterMotionState {
    std::vector<glm::mat4> previous, current;
    std::optional<uint32_t> frame;
};
// Per instance, the rows of prev x inverse(current) (a world point on the instance this frame -> where it
// was last frame; shaders/common/caster_motion.h); empty when there is no last frame, the instances
// changed, or no instance moved. casterMoved: a specular instance moved (the forward pass then carries
// each photon's caster motion); any moved instance moves the history of the pixels that show it.
struct InstanceMotion {
    std::vector<glm::vec4> rows;
    bool casterMoved = false;
};
InstanceMotion instanceMotion(CasterMotionState& state, const scene::Scene& scene, uint32_t frameIndex);

struct CausticResources::Impl {
    rhi::IDevice* device = nullptr;
    bool floatAtomics = true;
    bool int64Atomics = false;   // Capabilities::shaderBufferInt64Atomics: wide fixed-point words
    rhi::BindingLayoutHandle mapLayout, emitterLayout, forwardLayout, backwardLayout, gatherLayout;
    rhi::BindingLayoutHandle photonPlanLayout;
    rhi::ComputePipelineHandle photonPlanPipeline;   // caustic_maps/photon_plan_pass.cpp
    // Built against a scene binding layout (recreated when the scene's layout changes).
    const rhi::IBindingLayout* sceneLayoutSeen = nullptr;
    rhi::GraphicsPipelineHandle mapPipeline;
    rhi::ComputePipelineHandle emitterPipeline;   // scene set + emitterLayout
    rhi::BindingLayoutHandle gridLayout;
    rhi::ComputePipelineHandle gridFromCount;     // caustic_grid_pass.cpp
    rhi::BindingLayoutHandle specularPixelLayout;
    rhi::ComputePipelineHandle specularPixelPipeline;   // backward_trace/specular_pixels_pass.cpp
    rhi::BindingLayoutHandle secondTypeGuideLayout;
    rhi::ComputePipelineHandle secondTypeGuidePipeline;   // backward_trace/second_type_guides_pass.cpp
    rhi::BindingLayoutHandle secondTypeGuideFillLayout;
    rhi::ComputePipelineHandle secondTypeGuideFillPipeline;
    rhi::StateObjectHandle forwardState, backwardState, gatherState;
    rhi::ShaderTableHandle forwardTable, backwardTable, gatherTable;
    CausticFilterPipelines filter;   // resolve + filter (caustic_filter/)
    // The spheres' acceleration structure (docs/caustics.md, "Memory"): one AABB per sphere, written by
    // caustics.backward, in a bottom level rebuilt every frame under a top level of one instance. A top
    // level of one instance per sphere cost ~170 bytes a sphere; AABB leaves cost far less.
    rhi::BufferHandle sphereAabbs;       // VkAabbPositionsKHR / D3D12_RAYTRACING_AABB per slot (24 bytes)
    rhi::AccelStructHandle sphereBlas;   // over sphereAabbs
    rhi::AccelStructHandle sphereTlas;   // one instance of sphereBlas
    uint32_t sphereSlots = 0;   // AABB slots sphereAabbs and sphereBlas are allocated for (caustics/sphere_capacity.h)
    // The largest capacity a frame asked for past its allocation (set when a graph executes); the next
    // ensureSizeResources grows the allocation to it.
    uint32_t sphereAllocationWanted = 0;
    // Sphere AABB lists and BLASes replaced by larger ones, per frame slot: kept until that slot comes
    // round again, when the frames that may still trace them have finished (as frameSets).
    struct RetiredSphereStructure {
        rhi::BufferHandle aabbs;
        rhi::AccelStructHandle blas;
    };
    std::vector<std::vector<RetiredSphereStructure>> retiredSphereStructures;
    // Filter history textures replaced by a grown pool, per frame slot, kept the same way.
    std::vector<std::vector<rhi::TextureHandle>> retiredTextures;
    // Sphere counts read back per view (keyed by its history) and frame slot (backward_trace/caustics/sphere_capacity.h).
    std::map<uint64_t, std::vector<SphereCountReadback>> sphereCounts;   // by CausticViewHistory::viewId
    CausticViewHistory ownHistory;   // used when CausticFrameInputs::history is null
    CasterMotionState casterMotion;  // the instance transforms of the last two frames (caster_motion.cpp)
    // Per frame slot: the caster motion rows and per-pixel words (CausticFrame::instanceMotionRows,
    // casterMotionWords), persistent and grown on demand: as graph transients of a changing size they
    // aliased buffers whose device addresses lavapipe then lost track of ("unrecognized BDA").
    std::vector<rhi::BufferHandle> casterMotionRowBuffers, casterMotionWordBuffers;
    Status ensureCasterMotion(uint32_t slot, uint64_t rowBytes, uint64_t wordBytes);
    // Binding sets made while recording must outlive the GPU's use: kept for framesInFlight frames.
    std::vector<std::vector<rhi::BindingSetHandle>> frameSets;
    uint32_t frameSlot = 0;

    Status ensureScenePipelines(const rhi::BindingLayoutHandle& sceneLayout);
    Status ensureSizeResources(uint32_t pixels, uint32_t initialSphereAllocation, uint32_t frameSlot);
    Status ensureHistory(CausticViewHistory& history, uint32_t width, uint32_t height, uint32_t requestedPoolTiles);
    // Binding set for this frame (kept alive); null after logging the error.
    rhi::BindingSetHandle makeSet(rhi::IDevice& device, const rhi::BindingLayoutHandle& layout,
                                  rhi::BindingSetDesc desc);
    // The same from a pass's bindings filled by name (module/pass_bindings.h); an incomplete or wrong
    // set is logged with the pass's name (e.g. "caustics.forward") and gives null.
    rhi::BindingSetHandle makeSet(rhi::IDevice& device, const rhi::BindingLayoutHandle& layout, const char* pass,
                                  const PassBindingSet& bindings);
};

// Handles of one frame, filled pass by pass.
struct CausticFrame {
    const CausticFrameInputs* in = nullptr;
    CausticResources::Impl* res = nullptr;
    CausticViewHistory* history = nullptr;   // the view's (or res->ownHistory)
    uint32_t width = 0, height = 0;
    bool separateTypes = true;   // CausticFrameInputs::separateTypes; false: radiance2 is invalid
    // Fixed-point accumulation (floatAtomics off; docs/caustics.md "Fixed point"): one uint64 per channel
    // (wideFixedPoint) or one uint, holding value x fixedPointScale.
    bool wideFixedPoint = false;
    float fixedPointScale = kFixedPointScale;
    rg::RgBuffer camera, maps, radiance1, radiance2, hits, stats, spheres, sphereAabbs;
    rg::RgBuffer emitters, forwardArgs;   // caustics.emitters -> caustics.photonPlan -> caustics.forward
    rg::RgBuffer layerPlans, owners;      // CausticLayerPlanGpu per layer; CausticMapPlan::instanceLayers
    rg::RgBuffer specularPixels, backwardArgs;   // caustics.specularPixels -> caustics.backward
    // The second type in list order (common/specular_list.h; docs/caustics.md "Second-type memory"): its
    // buffer, resolved image and guides hold one texel per list entry (kSpecularListRow x listRows)
    // instead of one per pixel; specularIndex (R32UI, W x H) names each pixel's entry. Without list
    // order specularIndex is a 1 x 1 placeholder the passes bind and never read.
    bool secondTypeListOrder = false;
    uint32_t listRows = 0;
    rg::RgTexture specularIndex;
    // The sphere capacity of this frame, chosen when the graph executes (caustics/sphere_capacity.h).
    std::shared_ptr<uint32_t> sphereCapacity;
    uint32_t sphereAllocation = 0;   // slots of this frame's sphere list and AABB buffer
    // Records of caustics.hits: maxStoredHits, at most the forward pass's launches (one hit each; 0
    // without the second type, which alone reads them).
    uint32_t hitCapacity = 0;
    SphereCountReadback* sphereReadback = nullptr;   // this view's and slot's
    rg::RgTexture mapIds, mapDepth;
    rg::RgAccelStruct sphereBlas, sphereTlas;
    SecondTypeGuides secondTypeGuides;   // caustics.secondTypeGuides (invalid without the second type)
    // Appended to the filter's pass names: "" for the filter run on the camera G-buffer, ".secondType"
    // for the second type's own run (docs/caustics.md "Second-type guides"), so both are timed apart.
    const char* filterRun = "";
    // Instance and caster motion (docs/caustics.md "Moving casters", "Moving objects"): 3 rows per instance
    // (instanceMotion; empty when no instance moved), and the per-pixel sums the forward pass accumulates
    // from them (4 words per pixel when a caster moved, else a 16-byte placeholder the passes bind).
    // objectMotion: the temporal pass reprojects a moved instance's pixels with its rows.
    std::vector<glm::vec4> instanceMotion;
    bool casterMotion = false;
    bool objectMotion = false;
    rg::RgBuffer instanceMotionRows, casterMotionWords;
    CausticMapPlan plan;
    // The buffer the second type accumulates into: its own, or the first type's (one for both).
    rg::RgBuffer& secondTypeTarget() { return separateTypes ? radiance2 : radiance1; }
    const rg::RgBuffer& secondTypeTarget() const { return separateTypes ? radiance2 : radiance1; }
};

void addSetupPass(rg::RenderGraph& graph, CausticFrame& f);
void addMapPass(rg::RenderGraph& graph, CausticFrame& f);
void addEmitterPass(rg::RenderGraph& graph, CausticFrame& f);
void addPhotonPlanPass(rg::RenderGraph& graph, CausticFrame& f);
// The grid (min(stats[statSlot], cap), 1, 1) of an indirect ray dispatch, in a new 12-byte buffer;
// (0, 1, 1) when stats[gateSlot] is 0.
rg::RgBuffer addGridFromCountPass(rg::RenderGraph& graph, CausticFrame& f, const char* name, uint32_t statSlot,
                                  uint32_t cap, uint32_t gateSlot);
void addForwardPass(rg::RenderGraph& graph, CausticFrame& f);
// forward_trace/forward_pipeline.cpp: the forward pass's bindings (the variant of the device's
// atomics), its layout (with the other persistent objects) and its state (per scene layout).
const shader_bindings::PassBindings& forwardBindings(const CausticResources::Impl& r);
Status createForwardLayout(CausticResources::Impl& r);
Status createForwardState(CausticResources::Impl& r, const rhi::BindingLayoutHandle& sceneLayout);
// A ray-tracing state over the scene TLAS: `rayGen` with scene_trace/trace.rmiss and trace.rchit
// (the forward and backward passes; scene_trace/scene_trace_state.cpp).
Status sceneTraceState(rhi::IDevice& d, const char* rayGen, uint32_t pushBytes, const rhi::BindingLayoutHandle& scene,
                       const rhi::BindingLayoutHandle& pass, rhi::StateObjectHandle& so, rhi::ShaderTableHandle& table);
// backward_trace/backward_pipeline.cpp: the gather's bindings (the variant of the device's atomics),
// the second type's layouts, the specular-pixel pipeline and the gather state (with the other
// persistent objects), and the backward pass's state (per scene layout).
const shader_bindings::PassBindings& gatherBindings(const CausticResources::Impl& r);
Status createBackwardPipelines(CausticResources::Impl& r);
Status createBackwardState(CausticResources::Impl& r, const rhi::BindingLayoutHandle& sceneLayout);
void addBackwardPasses(rg::RenderGraph& graph, CausticFrame& f);
void addSpecularPixelPass(rg::RenderGraph& graph, CausticFrame& f);         // backward_trace/specular_pixels_pass.cpp
void addSecondTypeGuidePasses(rg::RenderGraph& graph, CausticFrame& f);     // backward_trace/second_type_guides_pass.cpp
// backward_trace/sphere_budget.cpp: the slot's read-back of the sphere count and f.sphereCapacity;
// the capacity from it (when the graph executes); the pass that copies this frame's count.
void prepareSphereBudget(CausticFrame& f);
// (Records in res a capacity wanted past `allocation`, which it never returns more than.)
uint32_t chooseSphereCapacity(CausticResources::Impl& res, const SphereCountReadback& slot, uint32_t width,
                              uint32_t height, uint32_t allocation);
void addSphereCountReadbackPass(rg::RenderGraph& graph, CausticFrame& f);
void addResolveAndFilterPasses(rg::RenderGraph& graph, CausticFrame& f, CausticOutputs& out);

// Binds one scene trace: the scene set (0), the pass's own set (1), push constants. The forward and
// backward passes differ only in these arguments (and dispatch from their GPU-counted grids).
template <typename PushConstants>
void bindSceneTrace(rhi::ICommandList& cmd, const rhi::StateObjectHandle& state, const rhi::ShaderTableHandle& table,
                    const rhi::BindingSetHandle& sceneSet, const rhi::BindingSetHandle& passSet,
                    const PushConstants& push) {
    cmd.setRayTracingState(state, table);
    cmd.setBindingSet(0, sceneSet);
    cmd.setBindingSet(1, passSet);
    cmd.setPushConstants(&push, sizeof(push));
}

}  // namespace caustics
