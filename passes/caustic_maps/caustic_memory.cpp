// What CausticResources and a view's filter history hold on the GPU (caustics/memory_report.h).
#include "caustic_internal.h"

namespace caustics {

void appendCausticMemory(CausticResources& resources, std::vector<MemoryEntry>& out) {
    CausticResources::Impl* r = resources.impl();
    if (!r) return;
    addMemoryEntry(out, "caustics.sphere_aabb", r->sphereAabb);
    addMemoryEntry(out, "caustics.sphere_blas", r->sphereBlas);
    addMemoryEntry(out, "caustics.sphere_tlas", r->sphereTlas);
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
    addMemoryEntry(out, prefix + ".color", history.color);
    addMemoryEntry(out, prefix + ".moments", history.moments);
    addMemoryEntry(out, prefix + ".depth", history.depth);
    addMemoryEntry(out, prefix + ".normal", history.normal);
    addMemoryEntry(out, prefix + ".object_id", history.objectId);
    addMemoryEntry(out, prefix + ".tiles0", history.tiles[0]);
    addMemoryEntry(out, prefix + ".tiles1", history.tiles[1]);
}

}  // namespace caustics
