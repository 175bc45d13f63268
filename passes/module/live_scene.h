#pragma once
// The scene as the GPU sees it, rewritten every frame from the host's scene::Scene (docs/embedding.md,
// "A live scene"): instances added, removed and moved, lights added, removed and changed, material
// parameters changed. Each frame-in-flight slot owns its instance, material and light tables
// (host-visible) and its TLAS, so a frame never overwrites what an earlier frame still reads; the
// "scene.update" pass writes the tables and rebuilds the TLAS on the GPU when they changed.
// Geometry (vertex, index buffers, BLASes) and textures come from the GpuScene and do not change.
#include <cstdint>
#include <vector>

#include "caustics/host_scene.h"
#include "caustics/memory_report.h"
#include "caustics/render_graph/render_graph.h"
#include "caustics/rhi/device.h"
#include "caustics/scene_bindings.h"
#include "caustics/scene/gpu_scene.h"
#include "caustics/scene/scene.h"

namespace caustics {

struct LiveSceneFrame {
    const SceneBindings* bindings = nullptr;   // set 0 of this frame
    rg::RgAccelStruct tlas;                    // passes that trace declare a read of it
};

class LiveScene {
public:
    static Result<LiveScene> create(rhi::IDevice& device, const scene::GpuScene& gpuScene, uint32_t framesInFlight);

    // Checks `scene` against the GPU scene (errors name the instance, mesh, material or texture), grows
    // slot `slot`'s tables when needed and adds the "scene.update" pass (never culled). Tables the host
    // hands in (`host`, each optional) are bound instead of the module's; a host TLAS is imported, not built.
    Result<LiveSceneFrame> addUpdatePass(rg::RenderGraph& graph, const scene::Scene& scene, uint32_t slot,
                                         const HostSceneTables& host = {});

    const rhi::BindingLayoutHandle& layout() const { return layout_; }
    // Each slot's own tables and TLAS (caustics/memory_report.h), named "scene.slot<N>.<table>"; the
    // geometry they share with the GpuScene is not repeated, a host's tables are not ours.
    void appendMemory(std::vector<MemoryEntry>& out) const;

    struct Slot;

private:
    rhi::IDevice* device_ = nullptr;
    const scene::GpuScene* gpuScene_ = nullptr;
    rhi::BindingLayoutHandle layout_;
    rhi::SamplerHandle sampler_;
    std::vector<std::shared_ptr<Slot>> slots_;
};

}  // namespace caustics
