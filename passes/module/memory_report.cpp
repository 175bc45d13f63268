#include "caustics/memory_report.h"

#include <algorithm>

#include "caustics/rhi/format.h"

namespace caustics {

const char* memoryKindName(MemoryKind kind) {
    switch (kind) {
        case MemoryKind::Persistent: return "persistent";
        case MemoryKind::Transient: return "transient";
        case MemoryKind::FramePeak: return "peak";
    }
    return "?";
}

uint64_t textureBytes(const rhi::TextureDesc& desc) {
    const uint64_t texel = rhi::formatInfo(desc.format).bytesPerPixel;
    uint64_t bytes = 0;
    uint64_t w = desc.width, h = desc.height;
    for (uint32_t mip = 0; mip < std::max(1u, desc.mipLevels); ++mip) {
        bytes += w * h * texel;
        w = std::max<uint64_t>(1, w / 2);
        h = std::max<uint64_t>(1, h / 2);
    }
    return bytes * std::max(1u, desc.arrayLayers);
}

void addMemoryEntry(std::vector<MemoryEntry>& out, std::string name, const rhi::BufferHandle& buffer) {
    if (buffer) out.push_back({std::move(name), buffer->desc().byteSize, MemoryKind::Persistent});
}

void addMemoryEntry(std::vector<MemoryEntry>& out, std::string name, const rhi::TextureHandle& texture) {
    if (texture) out.push_back({std::move(name), textureBytes(texture->desc()), MemoryKind::Persistent});
}

void addMemoryEntry(std::vector<MemoryEntry>& out, std::string name, const rhi::AccelStructHandle& accel) {
    if (accel) out.push_back({std::move(name), accel->storageBytes(), MemoryKind::Persistent});
}

uint64_t totalBytes(const std::vector<MemoryEntry>& entries) {
    uint64_t sum = 0;
    for (const MemoryEntry& e : entries) sum += e.bytes;
    return sum;
}

}  // namespace caustics

namespace caustics {

void appendFrameMemory(const rg::RenderGraph& graph, std::vector<MemoryEntry>& out) {
    const rg::CompiledPlan* plan = graph.plan();
    if (!plan) return;
    const auto& resources = graph.desc().resources;
    for (uint32_t i = 0; i < resources.size() && i < plan->heapOffset.size(); ++i)
        if (plan->heapOffset[i] && i < plan->memory.size())
            out.push_back({resources[i].name, plan->memory[i].size, MemoryKind::Transient});
    out.push_back({"frame.peak_transients", plan->heapSize, MemoryKind::FramePeak});
}

bool isHostSceneMemory(const MemoryEntry& e) {
    return e.kind == MemoryKind::Persistent && e.name.rfind("scene.", 0) == 0 && e.name.rfind("scene.slot", 0) != 0;
}

uint64_t moduleFrameBytes(const std::vector<MemoryEntry>& entries) {
    uint64_t sum = 0;
    for (const MemoryEntry& e : entries)
        if ((e.kind == MemoryKind::Persistent && !isHostSceneMemory(e)) || e.kind == MemoryKind::FramePeak) sum += e.bytes;
    return sum;
}

}  // namespace caustics
