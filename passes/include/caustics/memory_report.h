#pragma once
// GPU memory the caustics module holds, one entry per resource (docs/embedding.md, "Memory"): what a
// host engine adds to its own budget. CausticsModule::memoryReport() lists the persistent resources
// (scene geometry and BLASes of the GpuScene it renders, each frame slot's scene tables and TLAS, the
// sphere BLAS/TLAS of the second type, the sphere-count readbacks, the default view's camera buffers
// and filter history); a render graph's transients are listed by the host from its graph (kind
// Transient; the graph's heap may alias them). appendFrameMemory() adds a frame graph's transients and the
// peak they reach together in one frame (the graph's aliased heap).
#include <cstdint>
#include <string>
#include <vector>

#include "caustics/render_graph/render_graph.h"
#include "caustics/rhi/accel_struct.h"
#include "caustics/rhi/resources.h"

namespace caustics {

// FramePeak: one line per frame graph, what its transients occupy at once (the aliased heap the graph
// allocates; the Transient entries, before aliasing, add up to more).
enum class MemoryKind { Persistent, Transient, FramePeak };
const char* memoryKindName(MemoryKind kind);   // "persistent", "transient", "peak"

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
// Sum of every entry (mixing Transient entries with their FramePeak line counts the frame twice).
uint64_t totalBytes(const std::vector<MemoryEntry>& entries);

// A compiled frame graph (RenderGraph::compile or execute): one Transient entry per transient it
// places in its heap (size as the device asked, before aliasing), then the FramePeak line
// "frame.peak_transients" (the heap). Nothing before the graph is compiled.
void appendFrameMemory(const rg::RenderGraph& graph, std::vector<MemoryEntry>& out);

// The GpuScene the host passed to the module ("scene.*" except the module's own per-frame-slot
// "scene.slotN.*" tables and TLAS): the host's memory, which the module renders from.
bool isHostSceneMemory(const MemoryEntry& entry);
// What the module itself holds in one frame: every Persistent entry but the host's scene, plus the
// FramePeak lines (Transient entries are inside their peak).
uint64_t moduleFrameBytes(const std::vector<MemoryEntry>& entries);

}  // namespace caustics
