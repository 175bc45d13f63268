// Barrier planning: walk the kept passes in order and track each resource's state and whether its
// last access wrote it. A barrier is needed when the state changes (layout transition, D3D12 state
// transition), and also when the state stays the same but either side writes: read-after-write and
// write-after-write in UAV state (D3D12 "UAV barrier"; Vulkan execution + memory dependency) and
// render target -> render target across passes. Read -> read in the same state needs none.
#include <algorithm>

#include "compiler_internal.h"

namespace caustics::rg::detail {

using rhi::ResourceState;

Result<std::vector<PassUse>> passUses(const GraphDesc& graph, uint32_t pass) {
    const PassDecl& decl = graph.passes[pass];
    std::vector<PassUse> uses;
    std::vector<Access> firstAccess;
    for (const AccessDecl& a : decl.accesses) {
        const ResourceDecl& res = graph.resources[a.resource];
        ResourceState state = accessState(res.kind, a.access);
        auto it = std::find_if(uses.begin(), uses.end(), [&](const PassUse& u) { return u.resource == a.resource; });
        if (it == uses.end()) {
            uses.push_back({a.resource, state, a.write});
            firstAccess.push_back(a.access);
            continue;
        }
        bool write = it->writes || a.write;
        // Read-only states combine (D3D12 allows e.g. DepthRead | ShaderResource); a written resource
        // must be in exactly one state for the whole pass.
        if (write && it->state != state) {
            return makeError("render graph: pass '" + decl.name + "' uses " + resourceKindName(res.kind) + " '" +
                             res.name + "' both as " + accessName(firstAccess[size_t(it - uses.begin())]) +
                             " and as " + accessName(a.access) + "; a written resource needs one state per pass");
        }
        it->state = it->state | state;
        it->writes = write;
    }
    return uses;
}

namespace {
struct Track {
    ResourceState state = ResourceState::Undefined;
    bool lastWrite = false;
    bool live = false;
    bool touched = false;   // used by a kept pass
};

bool needsBarrier(const Track& t, ResourceState next, bool nextWrites) {
    if (t.state != next) return true;
    return t.lastWrite || nextWrites;
}
}  // namespace

Status planBarriers(const GraphDesc& graph, CompiledPlan& plan) {
    std::vector<Track> tracks(graph.resources.size());
    for (size_t r = 0; r < graph.resources.size(); ++r) {
        const ResourceDecl& res = graph.resources[r];
        if (res.imported) {
            // The host's earlier work may have written it: treat a write state as a pending write.
            tracks[r] = {res.initialState, rhi::isWriteState(res.initialState), true, false};
        }
    }
    for (PlannedPass& planned : plan.order) {
        auto uses = passUses(graph, planned.pass);
        if (!uses) return uses.error();
        for (const PassUse& use : *uses) {
            Track& t = tracks[use.resource];
            ResourceKind kind = graph.resources[use.resource].kind;
            if (!t.live) {
                bool aliasing = use.resource < plan.sharesMemory.size() && plan.sharesMemory[use.resource];
                planned.barriers.push_back({use.resource, kind, ResourceState::Undefined, use.state, true, aliasing});
            } else if (needsBarrier(t, use.state, use.writes)) {
                planned.barriers.push_back({use.resource, kind, t.state, use.state, false});
            }
            t = {use.state, use.writes, true, true};
        }
    }
    for (size_t r = 0; r < graph.resources.size(); ++r) {
        const ResourceDecl& res = graph.resources[r];
        const Track& t = tracks[r];
        if (!t.live) continue;
        // Undefined final state = the host does not care where it ends.
        if (res.finalState == ResourceState::Undefined || !(res.imported || res.output)) continue;
        // The host's later commands on the same queue must see the graph's last write, so a final
        // barrier is recorded even where the state already matches.
        if (t.state != res.finalState || (t.touched && t.lastWrite))
            plan.finalBarriers.push_back({uint32_t(r), res.kind, t.state, res.finalState, false});
    }
    return okStatus();
}

}  // namespace caustics::rg::detail
