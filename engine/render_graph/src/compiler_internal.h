#pragma once
// Steps of compileGraph() shared between its source files.
#include "caustics/render_graph/compiled_plan.h"

namespace caustics::rg::detail {

// The combined state of all accesses of one resource within one pass.
struct PassUse {
    uint32_t resource = kInvalidIndex;
    rhi::ResourceState state = rhi::ResourceState::Undefined;
    bool writes = false;
};

// Groups a pass's accesses by resource; fails when one pass needs two incompatible states.
Result<std::vector<PassUse>> passUses(const GraphDesc& graph, uint32_t pass);

// The pass's declared work, or the work its accesses leave no doubt about, else None (every stage).
rhi::PipelineStages passStages(const PassDecl& pass);
// Union of two sides of a barrier where None means "every stage" and so absorbs the other.
rhi::PipelineStages unionStages(rhi::PipelineStages a, rhi::PipelineStages b);

// Fills plan.order[*].barriers and plan.finalBarriers (plan.order and lifetimes already set).
Status planBarriers(const GraphDesc& graph, CompiledPlan& plan);

}  // namespace caustics::rg::detail
