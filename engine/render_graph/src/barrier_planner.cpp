// Barrier planning: walk the kept passes in order and track each resource's state and whether its
// last access wrote it. A barrier is needed when the state changes (layout transition, D3D12 state
// transition), and also when the state stays the same but either side writes: read-after-write and
// write-after-write in UAV state (D3D12 "UAV barrier"; Vulkan execution + memory dependency) and
// render target -> render target across passes. Read -> read in the same state needs none.
// Each barrier also carries the work on either side (docs/embedding.md "Barriers"): the kinds of the
// passes that used the resource since its last barrier, and the kind of the pass that uses it next.
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
    // The work of the passes that used it since its last barrier (None: every stage; the host's work
    // before an import).
    rhi::PipelineStages sinceBarrier = rhi::PipelineStages::None;
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
    // The memory of transients is shared across the frame (aliasing) and across frames (reuse), so a
    // transient's first use waits for the work of every pass that uses one.
    for (const PlannedPass& planned : plan.order) {
        const PassDecl& pass = graph.passes[planned.pass];
        bool usesTransient = false;
        for (const AccessDecl& a : pass.accesses) usesTransient |= !graph.resources[a.resource].imported;
        if (!usesTransient) continue;
        plan.transientStages =
            plan.transientsUsed ? unionStages(plan.transientStages, passStages(pass)) : passStages(pass);
        plan.transientsUsed = true;
    }
    std::vector<std::vector<PassUse>> uses;
    std::vector<rhi::PipelineStages> work;
    for (const PlannedPass& planned : plan.order) {
        auto passUsesOf = passUses(graph, planned.pass);
        if (!passUsesOf) return passUsesOf.error();
        uses.push_back(std::move(*passUsesOf));
        work.push_back(passStages(graph.passes[planned.pass]));
    }
    // A barrier into a read state serves every later reader in that state up to the next change (they
    // get no barrier of their own), so its destination is the work of all of them.
    auto readersFrom = [&](size_t position, const PassUse& use) {
        rhi::PipelineStages readers = work[position];
        for (size_t later = position + 1; later < uses.size() && !use.writes; ++later) {
            auto it = std::find_if(uses[later].begin(), uses[later].end(),
                                   [&](const PassUse& u) { return u.resource == use.resource; });
            if (it == uses[later].end()) continue;
            if (it->writes || it->state != use.state) break;
            readers = unionStages(readers, work[later]);
        }
        return readers;
    };
    for (size_t position = 0; position < plan.order.size(); ++position) {
        PlannedPass& planned = plan.order[position];
        for (const PassUse& use : uses[position]) {
            Track& t = tracks[use.resource];
            ResourceKind kind = graph.resources[use.resource].kind;
            rhi::PipelineStages since = unionStages(t.sinceBarrier, work[position]);
            if (!t.live) {
                bool aliasing = use.resource < plan.sharesMemory.size() && plan.sharesMemory[use.resource];
                planned.barriers.push_back({use.resource, kind, ResourceState::Undefined, use.state, true, aliasing,
                                            plan.transientStages, readersFrom(position, use)});
                since = work[position];
            } else if (needsBarrier(t, use.state, use.writes)) {
                planned.barriers.push_back({use.resource, kind, t.state, use.state, false, false, t.sinceBarrier,
                                            readersFrom(position, use)});
                since = work[position];
            }
            t = {use.state, use.writes, true, true, since};
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
            plan.finalBarriers.push_back({uint32_t(r), res.kind, t.state, res.finalState, false, false, t.sinceBarrier,
                                          rhi::PipelineStages::None});
    }
    return okStatus();
}

}  // namespace caustics::rg::detail
