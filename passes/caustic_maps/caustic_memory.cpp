// What CausticResources and a view's filter history hold on the GPU (caustics/memory_report.h).
#include "caustic_internal.h"

namespace caustics {

void appendCausticMemory(CausticResources& resources, std::vector<MemoryEntry>& out) {
    CausticResources::Impl* r = resources.impl();
    if (!r) return;
    addMemoryEntry(out, "caustics.sphere_aabbs", r->sphereAabbs);
    addMemoryEntry(out, "caustics.sphere_blas", r->sphereBlas);
    addMemoryEntry(out, "caustics.sphere_tlas", r->sphereTlas);
    // Caster motion (docs/caustics.md "Moving casters"), per frame slot: 16 bytes each unless a caster moved.
    for (size_t i = 0; i < r->casterMotionWordBuffers.size(); ++i) {
        addMemoryEntry(out, "caustics.slot" + std::to_string(i) + ".caster_motion", r->casterMotionWordBuffers[i]);
        addMemoryEntry(out, "caustics.slot" + std::to_string(i) + ".instance_motion", r->casterMotionRowBuffers[i]);
    }
    // One 4-byte readback per view and frame slot (sphere_capacity.h): summed, with their count.
    MemoryEntry readbacks{"caustics.sphere_count_readbacks", 0, MemoryKind::Persistent};
    uint32_t count = 0;
    for (const auto& [view, slots] : r->sphereCounts)
        for (const SphereCountReadback& slot : slots)
            if (slot.buffer) {
                readbacks.bytes += slot.buffer->desc().byteSize;
                ++count;
            }
    if (count > 0) {
        readbacks.name += " (" + std::to_string(count) + ")";
        out.push_back(readbacks);
    }
    appendHistoryMemory(r->ownHistory, "caustics.own_history", out);
}

void appendHistoryMemory(const CausticViewHistory& history, const std::string& prefix, std::vector<MemoryEntry>& out) {
    // Ping-ponged (caustic_passes.h): both copies, suffixed 0 and 1; the pools and the per-tile maps.
    for (uint32_t i = 0; i < 2; ++i) {
        const std::string n = std::to_string(i);
        addMemoryEntry(out, prefix + ".color" + n, history.color[i]);
        addMemoryEntry(out, prefix + ".guides" + n, history.guides[i]);
        addMemoryEntry(out, prefix + ".tiles" + n, history.tiles[i]);
        addMemoryEntry(out, prefix + ".slots" + n, history.slots[i]);
    }
    if (history.secondType) appendHistoryMemory(*history.secondType, prefix + ".second_type", out);
    MemoryEntry readbacks{prefix + ".tile_count_readbacks", 0, MemoryKind::Persistent};
    size_t count = 0;
    for (const rhi::BufferHandle& b : history.tileCounts)
        if (b) {
            readbacks.bytes += b->desc().byteSize;
            ++count;
        }
    if (count > 0) {
        readbacks.name += " (" + std::to_string(count) + ")";
        out.push_back(readbacks);
    }
}

}  // namespace caustics
