// Execution: realize transients (virtual resources bound into one heap at the planned offsets,
// reused across frames while descs and offsets match), then record barriers, passes and timestamps.
#include <algorithm>
#include <cstring>

#include "compiler_internal.h"
#include "execution_state.h"
#include "caustics/rhi/log.h"
#include "caustics/rhi/log_capture.h"

namespace caustics::rg {

bool sameTextureDesc(const rhi::TextureDesc& a, const rhi::TextureDesc& b) {
    return a.dimension == b.dimension && a.width == b.width && a.height == b.height &&
           a.arrayLayers == b.arrayLayers && a.mipLevels == b.mipLevels && a.format == b.format &&
           a.usage == b.usage && a.isVirtual == b.isVirtual &&
           std::memcmp(a.clearColor, b.clearColor, sizeof(a.clearColor)) == 0;
}

bool sameBufferDesc(const rhi::BufferDesc& a, const rhi::BufferDesc& b) {
    return a.byteSize == b.byteSize && a.usage == b.usage && a.memory == b.memory &&
           a.structStride == b.structStride && a.isVirtual == b.isVirtual;
}

namespace {
// Asks the device once per distinct desc and remembers the answer across frames.
class CachingMemorySizer final : public IMemorySizer {
public:
    CachingMemorySizer(rhi::IDevice& device, RenderGraph::ExecutionState& ex) : device_(device), ex_(ex) {}
    rhi::MemoryRequirements requirements(const rhi::TextureDesc& d) const override {
        for (const auto& [desc, req] : ex_.textureSizes)
            if (sameTextureDesc(desc, d)) return req;
        ex_.textureSizes.emplace_back(d, device_.memoryRequirements(d));
        return ex_.textureSizes.back().second;
    }
    rhi::MemoryRequirements requirements(const rhi::BufferDesc& d) const override {
        for (const auto& [desc, req] : ex_.bufferSizes)
            if (sameBufferDesc(desc, d)) return req;
        ex_.bufferSizes.emplace_back(d, device_.memoryRequirements(d));
        return ex_.bufferSizes.back().second;
    }

private:
    rhi::IDevice& device_;
    RenderGraph::ExecutionState& ex_;
};
}  // namespace

Status RenderGraph::realizeTransients(rhi::IDevice& device) {
    ExecutionState& ex = *exec_;
    const CompiledPlan& plan = *plan_;
    if (plan.heapSize > ex.heapSize) {
        CAUSTICS_TRY(ex.heap, device.createHeap({plan.heapSize, "render graph transients"}));
        ex.heapSize = plan.heapSize;
        // Resources bound to the old heap go with it.
        std::erase_if(ex.cache, [](const ExecutionState::CachedTransient& c) { return c.heapOffset.has_value(); });
    }
    for (auto& c : ex.cache) c.used = false;
    ex.physical = imported_;
    for (uint32_t r = 0; r < desc_.resources.size(); ++r) {
        const ResourceDecl& res = desc_.resources[r];
        if (res.imported || !plan.lifetimes[r].used()) continue;
        rhi::TextureDesc tdesc = plan.textureDescs[r];
        rhi::BufferDesc bdesc = plan.bufferDescs[r];
        if (tdesc.debugName.empty()) tdesc.debugName = res.name;
        if (bdesc.debugName.empty()) bdesc.debugName = res.name;
        auto match = std::find_if(ex.cache.begin(), ex.cache.end(), [&](const ExecutionState::CachedTransient& c) {
            if (c.used || c.kind != res.kind || c.heapOffset != plan.heapOffset[r]) return false;
            return res.kind == ResourceKind::Texture ? sameTextureDesc(c.textureDesc, tdesc)
                                                     : sameBufferDesc(c.bufferDesc, bdesc);
        });
        if (match == ex.cache.end()) {
            ExecutionState::CachedTransient entry;
            entry.kind = res.kind;
            entry.textureDesc = tdesc;
            entry.bufferDesc = bdesc;
            entry.heapOffset = plan.heapOffset[r];
            if (res.kind == ResourceKind::Texture) {
                CAUSTICS_TRY(entry.texture, device.createTexture(tdesc));
                if (entry.heapOffset) CAUSTICS_CHECK(device.bindMemory(entry.texture, ex.heap, *entry.heapOffset));
            } else if (res.kind == ResourceKind::Buffer) {
                CAUSTICS_TRY(entry.buffer, device.createBuffer(bdesc));
                if (entry.heapOffset) CAUSTICS_CHECK(device.bindMemory(entry.buffer, ex.heap, *entry.heapOffset));
            } else {
                return makeError("render graph: acceleration structure '" + res.name +
                                 "' must be imported (transient acceleration structures are not supported)");
            }
            ex.cache.push_back(std::move(entry));
            match = ex.cache.end() - 1;
        }
        match->used = true;
        ex.physical.textures[r] = match->texture;
        ex.physical.buffers[r] = match->buffer;
    }
    std::erase_if(ex.cache, [](const ExecutionState::CachedTransient& c) { return !c.used; });
    return okStatus();
}

namespace {
// `earlierFrames`: the work that used transient memory in frames executed before (an activation's
// source scope includes it; see ExecutionState::transientWork).
void recordBarriers(rhi::ICommandList& cmd, const std::vector<PlannedBarrier>& planned, const PhysicalResources& phys,
                    std::optional<rhi::PipelineStages> earlierFrames) {
    if (planned.empty()) return;
    std::vector<rhi::TextureBarrier> textures;
    std::vector<rhi::BufferBarrier> buffers;
    std::vector<rhi::AccelStructBarrier> accels;
    for (const PlannedBarrier& b : planned) {
        // A transient's first use in a frame waits for all earlier work on its memory, not only for
        // aliases inside this frame: transients and the heap are reused across frames, and an earlier
        // frame still in flight may be reading the same memory (write-after-read across frames).
        const bool waitForEarlierUse = b.aliasing || b.activation;
        const rhi::PipelineStages src =
            b.activation && earlierFrames ? detail::unionStages(b.srcStages, *earlierFrames) : b.srcStages;
        switch (b.kind) {
            case ResourceKind::Texture:
                textures.push_back({phys.textures[b.resource], b.before, b.after, {}, waitForEarlierUse, src, b.dstStages});
                break;
            case ResourceKind::Buffer:
                buffers.push_back({phys.buffers[b.resource], b.before, b.after, waitForEarlierUse, src, b.dstStages});
                break;
            case ResourceKind::AccelStruct:
                accels.push_back({phys.accelStructs[b.resource], b.before, b.after, src, b.dstStages});
                break;
        }
    }
    cmd.barriers(textures, buffers, accels);
}
}  // namespace

void RenderGraph::collectTimings(rhi::IDevice& device) {
    ExecutionState& ex = *exec_;
    if (!ex.timestampPool) return;
    for (uint32_t slot = 0; slot < ExecutionState::kTimestampSlots; ++slot) {
        auto& s = ex.slots[slot];
        if (!s.pending) continue;
        auto values = device.readTimestamps(ex.timestampPool, slot * 2 * ex.passesPerSlot, uint32_t(2 * s.passes.size()));
        bool ready = values.size() == 2 * s.passes.size() &&
                     std::all_of(values.begin(), values.end(), [](const auto& v) { return v.has_value(); });
        if (!ready) continue;
        for (size_t i = 0; i < s.passes.size(); ++i)
            timings_.add(s.passes[i], (*values[2 * i + 1] - *values[2 * i]) * 1e-6);
        s.pending = false;
    }
}

Status RenderGraph::execute(rhi::IDevice& device, rhi::ICommandList& cmd) {
    CAUSTICS_CHECK(compile(CachingMemorySizer(device, *exec_)));
    collectTimings(device);
    CAUSTICS_CHECK(realizeTransients(device));
    ExecutionState& ex = *exec_;
    const CompiledPlan& plan = *plan_;

    uint32_t passCount = uint32_t(plan.order.size());
    // A list that records no timestamps (a host's, wrapped with allowTimestamps = false) gets no pool:
    // nothing of ours is created on the host's device for them.
    const bool timestamps = cmd.recordsTimestamps();
    if (timestamps && !ex.timestampsUnavailable && passCount > ex.passesPerSlot) {
        uint32_t perSlot = std::max(passCount, 32u);
        auto pool = device.createTimestampPool(ExecutionState::kTimestampSlots * 2 * perSlot);
        if (pool) {
            ex.timestampPool = std::move(pool).value();
            ex.passesPerSlot = perSlot;
            for (auto& s : ex.slots) s.pending = false;
        } else {
            log(LogLevel::Warning, "render graph: no GPU timestamps (" + pool.message() + ")");
            ex.timestampsUnavailable = true;
        }
    }
    bool timed = timestamps && ex.timestampPool && passCount <= ex.passesPerSlot;
    uint32_t slot = uint32_t(ex.frame % ExecutionState::kTimestampSlots);
    uint32_t base = slot * 2 * ex.passesPerSlot;
    if (timed && passCount) cmd.resetTimestamps(ex.timestampPool, base, 2 * passCount);

    std::optional<rhi::PipelineStages> earlierFrames;
    if (ex.transientWorkSeen) earlierFrames = ex.transientWork;
    std::string firstError;
    std::vector<std::string> names;
    for (uint32_t i = 0; i < passCount; ++i) {
        const PlannedPass& planned = plan.order[i];
        const std::string& name = desc_.passes[planned.pass].name;
        names.push_back(name);
        recordBarriers(cmd, planned.barriers, ex.physical, earlierFrames);
        cmd.beginMarker(name);
        if (timed) cmd.writeTimestamp(ex.timestampPool, base + 2 * i);
        if (executes_[planned.pass]) {
            // An error the pass (or the RHI under it) only logs still fails execute(): a pass that
            // skipped its work must not leave the host with an ok and a black image.
            LogErrorCapture logged;
            PassContext ctx(&device, cmd, desc_, planned.pass, ex.physical);
            executes_[planned.pass](ctx);
            if (firstError.empty() && (ctx.failed() || logged.failed()))
                firstError = ctx.failed() ? ctx.error() : "render graph: pass '" + name + "': " + logged.firstError();
        }
        if (timed) cmd.writeTimestamp(ex.timestampPool, base + 2 * i + 1);
        cmd.endMarker();
    }
    recordBarriers(cmd, plan.finalBarriers, ex.physical, earlierFrames);
    if (plan.transientsUsed) {
        ex.transientWork = earlierFrames ? detail::unionStages(*earlierFrames, plan.transientStages) : plan.transientStages;
        ex.transientWorkSeen = true;
    }
    if (timed) ex.slots[slot] = {std::move(names), passCount > 0};
    ++ex.frame;
    if (!firstError.empty()) return makeError(firstError);
    return okStatus();
}

}  // namespace caustics::rg
