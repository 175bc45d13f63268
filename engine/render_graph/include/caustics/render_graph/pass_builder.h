#pragma once
// Setup phase: a pass declares every resource it touches and how. Writes return the next version of
// the handle; later passes must use that version (an older one is rejected at compile time).
#include <string>

#include "caustics/render_graph/access.h"
#include "caustics/render_graph/resource_handle.h"
#include "caustics/rhi/pipeline_stages.h"
#include "caustics/rhi/resources.h"

namespace caustics::rg {

class RenderGraph;

class PassBuilder {
public:
    // Transient resources: the graph creates them (aliased in one heap where possible). Usage flags
    // the declared accesses need are added to the desc.
    RgTexture createTexture(std::string name, const rhi::TextureDesc& desc);
    RgBuffer createBuffer(std::string name, const rhi::BufferDesc& desc);

    RgTexture read(RgTexture texture, Access access = Access::SampledRead);
    RgBuffer read(RgBuffer buffer, Access access = Access::SampledRead);
    RgAccelStruct read(RgAccelStruct as, Access access = Access::AccelStructTrace);

    RgTexture write(RgTexture texture, Access access = Access::StorageWrite);
    RgBuffer write(RgBuffer buffer, Access access = Access::StorageWrite);
    RgAccelStruct write(RgAccelStruct as, Access access = Access::AccelStructBuild);

    // The pass does something the graph cannot see (host readback, present): never cull it.
    void setSideEffects() { sideEffects_ = true; }
    // The kind of work the pass records (dispatch: Compute, dispatchRays: RayTracing, draws: Raster,
    // copies and clears: Copy, AS builds: AccelStructBuild; several may be OR-ed). The graph's barriers
    // then wait only for these stages and block only these (docs/embedding.md "Barriers"). Not said,
    // the graph infers it from the accesses where they leave no doubt (attachments: Raster, copy
    // accesses alone: Copy, AS build accesses alone: AccelStructBuild), else waits for every stage.
    void setStages(rhi::PipelineStages stages);

private:
    friend class RenderGraph;
    PassBuilder(RenderGraph& graph, uint32_t pass) : graph_(graph), pass_(pass) {}
    uint32_t access(ResourceKind kind, uint32_t index, uint32_t version, Access access, bool write);

    RenderGraph& graph_;
    uint32_t pass_;
    bool sideEffects_ = false;
};

}  // namespace caustics::rg
