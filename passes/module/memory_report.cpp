#include "caustics/memory_report.h"

#include <algorithm>

#include "caustics/rhi/format.h"

namespace caustics {

const char* memoryKindName(MemoryKind kind) { return kind == MemoryKind::Persistent ? "persistent" : "transient"; }

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
