#pragma once
// What RenderGraph keeps between frames: the transient heap and the resources placed in it (reused
// while descs and offsets match), and a ring of timestamp slots for frames still in flight.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "caustics/render_graph/render_graph.h"

namespace caustics::rg {

struct RenderGraph::ExecutionState {
    // Frames whose timestamps may still be unread (typical swap-chain depth of 2-3 frames in flight).
    static constexpr uint32_t kTimestampSlots = 3;

    struct CachedTransient {
        ResourceKind kind = ResourceKind::Texture;
        rhi::TextureDesc textureDesc;
        rhi::BufferDesc bufferDesc;
        std::optional<uint64_t> heapOffset;
        rhi::TextureHandle texture;
        rhi::BufferHandle buffer;
        bool used = false;
    };
    struct TimestampSlot {
        std::vector<std::string> passes;   // names, in execution order
        bool pending = false;
    };

    // The work of every pass that used a transient in an executed frame (None: some pass of unknown
    // kind, i.e. every stage): a transient's first use waits for it, since an earlier frame still in
    // flight may be using the same memory.
    rhi::PipelineStages transientWork = rhi::PipelineStages::None;
    bool transientWorkSeen = false;

    rhi::HeapHandle heap;
    uint64_t heapSize = 0;
    std::vector<CachedTransient> cache;
    PhysicalResources physical;

    rhi::TimestampPoolHandle timestampPool;
    uint32_t passesPerSlot = 0;
    bool timestampsUnavailable = false;
    std::array<TimestampSlot, kTimestampSlots> slots;
    uint64_t frame = 0;

    // Memory requirements per desc: asking the device may create a probe object, too slow per frame.
    std::vector<std::pair<rhi::TextureDesc, rhi::MemoryRequirements>> textureSizes;
    std::vector<std::pair<rhi::BufferDesc, rhi::MemoryRequirements>> bufferSizes;
};

bool sameTextureDesc(const rhi::TextureDesc& a, const rhi::TextureDesc& b);
bool sameBufferDesc(const rhi::BufferDesc& a, const rhi::BufferDesc& b);

}  // namespace caustics::rg
