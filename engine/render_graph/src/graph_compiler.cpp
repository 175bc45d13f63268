// compileGraph: validation, culling (Frostbite-style reverse reachability from outputs and
// side-effect passes), ordering, lifetimes, transient descs, heap placement and barriers.
#include <algorithm>
#include <set>
#include <string>

#include "compiler_internal.h"
#include "caustics/render_graph/memory_aliasing.h"

namespace caustics::rg {
namespace {

std::string describe(const GraphDesc& g, uint32_t pass, uint32_t resource) {
    return "pass '" + g.passes[pass].name + "', " + resourceKindName(g.resources[resource].kind) + " '" +
           g.resources[resource].name + "'";
}

// Reads must name the version current when the pass starts (or the pass's own output); writes
// produce exactly start + 1. Also records the producer of every version.
Status validate(const GraphDesc& g, std::vector<std::vector<uint32_t>>& producers) {
    std::vector<uint32_t> current(g.resources.size(), 0);
    producers.assign(g.resources.size(), {});
    for (size_t r = 0; r < g.resources.size(); ++r) producers[r].assign(1, kInvalidIndex);
    for (uint32_t p = 0; p < g.passes.size(); ++p) {
        std::set<uint32_t> written;
        for (const AccessDecl& a : g.passes[p].accesses) {
            if (a.resource >= g.resources.size())
                return makeError("render graph: pass '" + g.passes[p].name + "' uses an unknown resource");
            const ResourceDecl& res = g.resources[a.resource];
            if (!accessValidFor(res.kind, a.access))
                return makeError("render graph: " + describe(g, p, a.resource) + ": access " + accessName(a.access) +
                                 " is not valid for a " + resourceKindName(res.kind));
            if (a.write) {
                if (a.version != current[a.resource] + 1)
                    return makeError("render graph: " + describe(g, p, a.resource) + ": writes version " +
                                     std::to_string(a.version - 1) + " but version " +
                                     std::to_string(current[a.resource]) + " is current");
                written.insert(a.resource);
            }
        }
        for (const AccessDecl& a : g.passes[p].accesses) {
            if (a.write) continue;
            bool ownOutput = written.count(a.resource) && a.version == current[a.resource] + 1;
            if (a.version != current[a.resource] && !ownOutput)
                return makeError("render graph: " + describe(g, p, a.resource) + ": reads version " +
                                 std::to_string(a.version) + " but version " + std::to_string(current[a.resource]) +
                                 " is current (a later write made the handle stale)");
            if (a.version == 0 && !g.resources[a.resource].imported)
                return makeError("render graph: " + describe(g, p, a.resource) +
                                 ": reads a transient that no earlier pass wrote");
        }
        for (uint32_t r : written) {
            ++current[r];
            producers[r].push_back(p);
        }
    }
    for (size_t r = 0; r < g.resources.size(); ++r)
        if (g.resources[r].latestVersion != current[r])
            return makeError("render graph: resource '" + g.resources[r].name + "' has latestVersion " +
                             std::to_string(g.resources[r].latestVersion) + " but its passes wrote " +
                             std::to_string(current[r]) + " versions");
    return okStatus();
}

// A pass is kept when it has side effects or produces a version somebody kept needs. A write may be
// partial, so a kept writer also needs the version before it (conservative: never culls a producer
// whose data might survive in the output).
std::vector<bool> cull(const GraphDesc& g) {
    std::set<std::pair<uint32_t, uint32_t>> needed;
    for (uint32_t r = 0; r < g.resources.size(); ++r)
        if (g.resources[r].output) needed.insert({r, g.resources[r].latestVersion});
    std::vector<bool> kept(g.passes.size(), false);
    for (uint32_t p = uint32_t(g.passes.size()); p-- > 0;) {
        const PassDecl& pass = g.passes[p];
        bool alive = pass.sideEffects;
        for (const AccessDecl& a : pass.accesses)
            if (a.write && needed.count({a.resource, a.version})) alive = true;
        if (!alive) continue;
        kept[p] = true;
        for (const AccessDecl& a : pass.accesses) {
            if (a.write) needed.insert({a.resource, a.version - 1});
            else needed.insert({a.resource, a.version});
        }
    }
    return kept;
}

// What a library handed to the host (GraphDesc::expectedConsumers) must reach it: one of each group
// is consumed when the producer of its latest version is kept (the host reads it, or another output
// of that pass) or a kept pass reads it. Otherwise culling drops its producers silently.
bool consumed(const GraphDesc& g, const std::vector<bool>& kept, uint32_t r) {
    const ResourceDecl& res = g.resources[r];
    if (res.output) return true;
    for (uint32_t p = 0; p < g.passes.size(); ++p) {
        if (!kept[p]) continue;
        for (const AccessDecl& a : g.passes[p].accesses)
            if (a.resource == r && (a.version == res.latestVersion || (a.write && a.version - 1 == res.latestVersion)))
                return true;
    }
    return false;
}

Status checkExpectedConsumers(const GraphDesc& g, const std::vector<bool>& kept) {
    for (const ExpectedConsumer& e : g.expectedConsumers) {
        bool any = false;
        std::string names;
        for (uint32_t r : e.anyOf) {
            if (r >= g.resources.size()) continue;
            any = any || consumed(g, kept, r);
            names += (names.empty() ? "'" : ", '") + g.resources[r].name + "'";
        }
        if (!any)
            return makeError("render graph: none of " + names + " from " + e.owner +
                             " is read by a pass or marked as an output, so the graph would cull every pass that "
                             "makes them: call graph.markOutput(...) on the one you use or read it in a pass");
    }
    return okStatus();
}

void addDependencies(const GraphDesc& g, const std::vector<std::vector<uint32_t>>& producers, CompiledPlan& plan) {
    std::set<std::tuple<uint32_t, uint32_t, uint32_t, uint32_t>> seen;
    for (const PlannedPass& pp : plan.order) {
        for (const AccessDecl& a : g.passes[pp.pass].accesses) {
            uint32_t version = a.write ? a.version - 1 : a.version;
            if (version == 0 || version >= producers[a.resource].size()) continue;
            uint32_t producer = producers[a.resource][version];
            if (producer == pp.pass || !plan.passKept[producer]) continue;
            if (seen.insert({producer, pp.pass, a.resource, version}).second)
                plan.dependencies.push_back({producer, pp.pass, a.resource, version});
        }
    }
}

}  // namespace

Result<CompiledPlan> compileGraph(const GraphDesc& g, const IMemorySizer& sizer) {
    std::vector<std::vector<uint32_t>> producers;
    CAUSTICS_CHECK(validate(g, producers));
    for (uint32_t p = 0; p < g.passes.size(); ++p) CAUSTICS_CHECK(detail::passUses(g, p));

    CompiledPlan plan;
    plan.passKept = cull(g);
    CAUSTICS_CHECK(checkExpectedConsumers(g, plan.passKept));
    // Declaration order is a valid topological order (a pass can only read versions that earlier
    // passes wrote), and keeps the host's intended order as the tie-break.
    for (uint32_t p = 0; p < g.passes.size(); ++p)
        if (plan.passKept[p]) plan.order.push_back({p, {}});
    addDependencies(g, producers, plan);

    const size_t n = g.resources.size();
    plan.lifetimes.assign(n, Lifetime{});
    plan.textureDescs.resize(n);
    plan.bufferDescs.resize(n);
    plan.memory.assign(n, {});
    plan.heapOffset.assign(n, std::nullopt);
    for (size_t r = 0; r < n; ++r) {
        plan.textureDescs[r] = g.resources[r].textureDesc;
        plan.bufferDescs[r] = g.resources[r].bufferDesc;
    }
    for (uint32_t pos = 0; pos < plan.order.size(); ++pos) {
        for (const AccessDecl& a : g.passes[plan.order[pos].pass].accesses) {
            Lifetime& life = plan.lifetimes[a.resource];
            life.first = std::min(life.first, pos);
            life.last = std::max(life.last, pos);
            plan.textureDescs[a.resource].usage = plan.textureDescs[a.resource].usage | requiredTextureUsage(a.access);
            plan.bufferDescs[a.resource].usage = plan.bufferDescs[a.resource].usage | requiredBufferUsage(a.access);
        }
    }

    std::vector<AliasRequest> requests;
    std::vector<uint32_t> requestResource;
    for (uint32_t r = 0; r < n; ++r) {
        const ResourceDecl& res = g.resources[r];
        Lifetime& life = plan.lifetimes[r];
        if (!life.used()) continue;
        // The host reads an output after the graph: it must survive past the last pass.
        if (res.output && !plan.order.empty()) life.last = uint32_t(plan.order.size() - 1);
        if (res.imported || res.kind == ResourceKind::AccelStruct) continue;
        // Host-visible buffers keep their own memory (the heap is device-local).
        if (res.kind == ResourceKind::Buffer && res.bufferDesc.memory != rhi::MemoryType::DeviceLocal) continue;
        // So do indirect-argument buffers (a few bytes each): a driver may find them by device address,
        // and lavapipe's address table loses a buffer whose start address an aliased buffer shares
        // once that one is destroyed ("unrecognized BDA!" at an indirect ray dispatch, then abort).
        if (res.kind == ResourceKind::Buffer && rhi::hasAny(plan.bufferDescs[r].usage, rhi::BufferUsage::Indirect)) continue;
        if (res.kind == ResourceKind::Texture) {
            plan.textureDescs[r].isVirtual = true;
            plan.memory[r] = sizer.requirements(plan.textureDescs[r]);
        } else {
            plan.bufferDescs[r].isVirtual = true;
            plan.memory[r] = sizer.requirements(plan.bufferDescs[r]);
        }
        // The device's requirements already keep a buffer and an image off each other's
        // bufferImageGranularity page (the Vulkan backend pads them to it: rhi/vulkan/vk_device.cpp).
        uint64_t alignment = std::max<uint64_t>(plan.memory[r].alignment, 1);
        requests.push_back({plan.memory[r].size, alignment, life});
        requestResource.push_back(r);
    }
    AliasPlacement placement = placeAliased(requests);
    for (size_t i = 0; i < requests.size(); ++i) plan.heapOffset[requestResource[i]] = placement.offsets[i];
    plan.heapSize = placement.heapSize;
    plan.sharesMemory.assign(n, false);
    for (size_t i = 0; i < requests.size(); ++i)
        for (size_t j = i + 1; j < requests.size(); ++j) {
            uint64_t a = placement.offsets[i], b = placement.offsets[j];
            if (a < b + requests[j].size && b < a + requests[i].size)
                plan.sharesMemory[requestResource[i]] = plan.sharesMemory[requestResource[j]] = true;
        }

    CAUSTICS_CHECK(detail::planBarriers(g, plan));
    return plan;
}

}  // namespace caustics::rg
