#pragma once
// The device-free description of one frame's graph: what the setup phase declared. RenderGraph builds
// it through PassBuilder; compileGraph() turns it into a CompiledPlan. Tests may also fill it directly.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "caustics/render_graph/access.h"
#include "caustics/render_graph/resource_handle.h"
#include "caustics/rhi/pipeline_stages.h"
#include "caustics/rhi/resource_state.h"
#include "caustics/rhi/resources.h"

namespace caustics::rg {

struct ResourceDecl {
    ResourceKind kind = ResourceKind::Texture;
    std::string name;
    bool imported = false;
    rhi::TextureDesc textureDesc;   // transient textures
    rhi::BufferDesc bufferDesc;     // transient buffers
    // Imported: the state the host leaves it in before the graph and wants it in afterwards.
    rhi::ResourceState initialState = rhi::ResourceState::Undefined;
    rhi::ResourceState finalState = rhi::ResourceState::Undefined;
    // Output: the host reads it after the graph, so its producers are never culled. A transient
    // output lives to the end of the graph and is left in finalState (Undefined = its last state).
    bool output = false;
    uint32_t latestVersion = 0;     // bumped by every write
};

struct AccessDecl {
    uint32_t resource = kInvalidIndex;
    // Reads: the version read. Writes: the version produced (the previous one is read implicitly,
    // because a write may be partial; see compileGraph's culling).
    uint32_t version = 0;
    Access access = Access::SampledRead;
    bool write = false;
};

struct PassDecl {
    std::string name;
    bool sideEffects = false;   // never culled (e.g. writes a host-visible buffer or presents)
    // The kind of work the pass records (PassBuilder::setStages); None = inferred from its accesses
    // where they leave no doubt, else every stage (passStages()).
    rhi::PipelineStages stages = rhi::PipelineStages::None;
    std::vector<AccessDecl> accesses;
};

// Resources a library handed to the host (e.g. CausticsModule::addPasses' outputs): at least one must be
// read by a kept pass or marked as an output, else compile() fails, since culling would drop every
// pass that makes them without a word (RenderGraph::expectConsumer).
struct ExpectedConsumer {
    std::string owner;
    std::vector<uint32_t> anyOf;   // resource indices
};

struct GraphDesc {
    std::vector<ResourceDecl> resources;
    std::vector<PassDecl> passes;
    std::vector<ExpectedConsumer> expectedConsumers;
};

}  // namespace caustics::rg
