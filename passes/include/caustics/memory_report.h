#pragma once
// GPU memory the caustics module holds, one entry per resource (docs/embedding.md, "Memory"): what a
// host engine adds to its own budget. CausticsModule::memoryReport() lists the persistent resources
// (scene geometry and BLASes of the GpuScene it renders, each frame slot's scene tables and TLAS, the
// sphere BLAS/TLAS of the second type, the sphere-count readbacks, the default view's camera buffers
// and filter history); a render graph's transients are listed by the host from its graph (kind
// Transient; the graph's heap may alias them).
#include <cstdint>
#include <string>
#include <vector>

#include "caustics/rhi/accel_struct.h"
#include "caustics/rhi/resources.h"

namespace caustics {

enum class MemoryKind { Persistent, Transient };
const char* memoryKindName(MemoryKind kind);   // "persistent", "transient"

struct MemoryEntry {
    std::string name;
    uint64_t bytes = 0;   // buffers: their size; textures: texel bytes of every mip and layer;
                          // acceleration structures: the backing buffer the driver asked for
    MemoryKind kind = MemoryKind::Persistent;
};

// Appends one entry (nothing for a null handle).
void addMemoryEntry(std::vector<MemoryEntry>& out, std::string name, const rhi::BufferHandle& buffer);
void addMemoryEntry(std::vector<MemoryEntry>& out, std::string name, const rhi::TextureHandle& texture);
void addMemoryEntry(std::vector<MemoryEntry>& out, std::string name, const rhi::AccelStructHandle& accel);

uint64_t textureBytes(const rhi::TextureDesc& desc);
uint64_t totalBytes(const std::vector<MemoryEntry>& entries);

}  // namespace caustics
