#pragma once
// What the compiler decides for one frame: passes kept and their order, the barriers before each pass
// and after the last one, resource lifetimes and heap offsets of the transients.
#include <cstdint>
#include <optional>
#include <vector>

#include "caustics/render_graph/graph_desc.h"
#include "caustics/render_graph/memory_sizer.h"
#include "caustics/rhi/result.h"

namespace caustics::rg {

struct PlannedBarrier {
    uint32_t resource = kInvalidIndex;
    ResourceKind kind = ResourceKind::Texture;
    rhi::ResourceState before = rhi::ResourceState::Undefined;
    rhi::ResourceState after = rhi::ResourceState::Undefined;
    // First use of a transient: its contents are undefined (and its memory may have held another
    // transient until now), so the transition starts from Undefined.
    bool activation = false;
    // Activation of a transient whose heap range other transients also use (at other times): the
    // barrier must also wait for earlier work on that memory (rhi::TextureBarrier::aliasing).
    bool aliasing = false;
    // The work that used the resource since its last barrier and the work that uses it next (rhi
    // barrier's beforeStages/afterStages). None = every stage: the host's work before an import or after
    // the graph, or a pass whose kind is unknown. An activation's source is the work of every kept pass
    // that uses a transient (the memory's earlier users, in this frame or an earlier one still in flight);
    // execute() adds the work of earlier frames.
    rhi::PipelineStages srcStages = rhi::PipelineStages::None;
    rhi::PipelineStages dstStages = rhi::PipelineStages::None;
};

struct PlannedPass {
    uint32_t pass = kInvalidIndex;         // index into GraphDesc::passes
    std::vector<PlannedBarrier> barriers;  // recorded before the pass
};

// Positions in CompiledPlan::order (not declaration indices); first > last means never used.
struct Lifetime {
    uint32_t first = kInvalidIndex;
    uint32_t last = 0;
    bool used() const { return first != kInvalidIndex; }
    bool overlaps(const Lifetime& o) const { return used() && o.used() && first <= o.last && o.first <= last; }
};

// A producer -> consumer dependency between two kept passes through one resource version.
struct Dependency {
    uint32_t producer = kInvalidIndex;   // declaration index
    uint32_t consumer = kInvalidIndex;
    uint32_t resource = kInvalidIndex;
    uint32_t version = 0;
};

struct CompiledPlan {
    std::vector<bool> passKept;              // per declared pass
    std::vector<PlannedPass> order;          // kept passes in execution order
    std::vector<PlannedBarrier> finalBarriers;
    std::vector<Lifetime> lifetimes;         // per resource
    std::vector<rhi::TextureDesc> textureDescs;  // per resource: user desc + usages the accesses need
    std::vector<rhi::BufferDesc> bufferDescs;
    std::vector<rhi::MemoryRequirements> memory;  // per transient placed in the heap
    std::vector<std::optional<uint64_t>> heapOffset;  // per resource; set for heap-placed transients
    std::vector<bool> sharesMemory;   // per resource: its heap range overlaps another transient's
    uint64_t heapSize = 0;
    std::vector<Dependency> dependencies;
    // The work of every kept pass that uses a transient (None if one of them is of unknown kind).
    rhi::PipelineStages transientStages = rhi::PipelineStages::None;
    bool transientsUsed = false;

    const PlannedPass* findPass(uint32_t declIndex) const {
        for (const PlannedPass& p : order)
            if (p.pass == declIndex) return &p;
        return nullptr;
    }
};

// Validates, culls, orders, computes lifetimes, aliases transient memory and plans every barrier.
// Errors name the pass and resource at fault.
Result<CompiledPlan> compileGraph(const GraphDesc& graph, const IMemorySizer& sizer);

}  // namespace caustics::rg
