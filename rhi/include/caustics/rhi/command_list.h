#pragma once
// Command recording. Barriers are explicit (before -> after states); nothing is tracked implicitly,
// so a render graph (or the caller) owns every transition.
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "caustics/rhi/accel_struct.h"
#include "caustics/rhi/pipeline.h"
#include "caustics/rhi/pipeline_stages.h"
#include "caustics/rhi/state_object.h"

namespace caustics::rhi {

struct TextureSubresources {
    uint32_t baseMip = 0, mipCount = ~0u;       // ~0u = all remaining
    uint32_t baseLayer = 0, layerCount = ~0u;
};

struct TextureBarrier {
    TextureHandle texture;
    ResourceState before = ResourceState::Undefined;
    ResourceState after = ResourceState::Common;
    TextureSubresources subresources;
    // The texture's memory held other (aliased) resources until now, e.g. a render-graph transient
    // placed over an earlier one: the transition must wait for all earlier work on that memory
    // (D3D12 aliasing barrier; Vulkan: src stage ALL_COMMANDS, src access MEMORY_WRITE). Added by the
    // render graph; a plain Undefined source waits for nothing.
    bool aliasing = false;
    // The work that last used the texture (or, with `aliasing`, its memory) and the work that uses it
    // next. None = every stage the state allows (Vulkan: all shader stages; an aliasing barrier then
    // waits for ALL_COMMANDS). The render graph sets both from its passes' kinds.
    PipelineStages beforeStages = PipelineStages::None;
    PipelineStages afterStages = PipelineStages::None;
};
struct BufferBarrier {
    BufferHandle buffer;
    ResourceState before = ResourceState::Undefined;
    ResourceState after = ResourceState::Common;
    bool aliasing = false;   // as TextureBarrier::aliasing
    PipelineStages beforeStages = PipelineStages::None;   // as TextureBarrier's
    PipelineStages afterStages = PipelineStages::None;
};
// Orders AS builds against later builds and traces (D3D12: UAV barrier on the AS).
struct AccelStructBarrier {
    AccelStructHandle accelStruct;
    ResourceState before = ResourceState::AccelStructWrite;
    ResourceState after = ResourceState::AccelStructRead;
    PipelineStages beforeStages = PipelineStages::None;   // as TextureBarrier's
    PipelineStages afterStages = PipelineStages::None;
};

// One mip level of one array layer, and a rectangle in it. width/height 0 = to the edge of the mip.
struct TextureRegion {
    uint32_t layer = 0, mip = 0;
    uint32_t x = 0, y = 0;
    uint32_t width = 0, height = 0;
    TextureRegion& setLayer(uint32_t v) { layer = v; return *this; }
    TextureRegion& setMip(uint32_t v) { mip = v; return *this; }
    TextureRegion& setOffset(uint32_t vx, uint32_t vy) { x = vx; y = vy; return *this; }
    TextureRegion& setSize(uint32_t w, uint32_t h) { width = w; height = h; return *this; }
};

struct ColorAttachment {
    TextureHandle texture;
    uint32_t layer = 0;
    bool clear = false;
    float clearValue[4] = {0, 0, 0, 0};
};
struct DepthAttachment {
    TextureHandle texture;
    uint32_t layer = 0;
    bool clear = false;
    float clearDepth = 1.0f;
};
struct RenderingDesc {
    std::vector<ColorAttachment> colors;
    DepthAttachment depth;   // texture null = none
    uint32_t width = 0, height = 0;
};

class ITimestampPool {
public:
    virtual ~ITimestampPool() = default;
    virtual uint32_t capacity() const = 0;
};
using TimestampPoolHandle = std::shared_ptr<ITimestampPool>;

class ICommandList {
public:
    virtual ~ICommandList() = default;

    virtual void begin() = 0;   // resets and starts recording
    virtual void end() = 0;

    virtual void barriers(std::span<const TextureBarrier> textures, std::span<const BufferBarrier> buffers,
                          std::span<const AccelStructBarrier> accelStructs = {}) = 0;
    void barrier(const TextureBarrier& b) { barriers({&b, 1}, {}); }
    void barrier(const BufferBarrier& b) { barriers({}, {&b, 1}); }
    void barrier(const AccelStructBarrier& b) { barriers({}, {}, {&b, 1}); }

    // Copies and transfers. Textures must be in CopySource/CopyDest, buffers in CopySource/CopyDest.
    virtual void writeBuffer(const BufferHandle& dst, const void* data, uint64_t bytes, uint64_t dstOffset = 0) = 0;
    virtual void copyBuffer(const BufferHandle& dst, uint64_t dstOffset, const BufferHandle& src, uint64_t srcOffset,
                            uint64_t bytes) = 0;
    virtual void fillBuffer(const BufferHandle& dst, uint32_t value, uint64_t offset = 0, uint64_t bytes = ~0ull) = 0;
    // Tightly packed rows; layer selects an array layer.
    virtual void writeTexture(const TextureHandle& dst, uint32_t layer, uint32_t mip, const void* data,
                              uint64_t bytes) = 0;
    // Texture to texture on the GPU: `srcRegion`'s rectangle lands at dstRegion's layer, mip and offset
    // (dstRegion's size is ignored). Both formats must have the same bytes per texel; src in CopySource,
    // dst in CopyDest. A region outside either texture is a recording error (reported by submit).
    virtual void copyTexture(const TextureHandle& dst, const TextureRegion& dstRegion, const TextureHandle& src,
                             const TextureRegion& srcRegion) = 0;
    virtual void copyTextureToBuffer(const BufferHandle& dst, uint64_t dstOffset, const TextureHandle& src,
                                     uint32_t layer = 0, uint32_t mip = 0) = 0;
    // Texture in CopyDest. Float formats take `value` as floats, integer formats as bit patterns.
    virtual void clearTextureFloat(const TextureHandle& texture, const float value[4]) = 0;
    virtual void clearTextureUint(const TextureHandle& texture, const uint32_t value[4]) = 0;

    // Compute.
    virtual void setComputePipeline(const ComputePipelineHandle& pipeline) = 0;
    virtual void dispatch(uint32_t x, uint32_t y = 1, uint32_t z = 1) = 0;
    // As dispatch, with the group counts read by the GPU: three uint32 (x, y, z) at `offset` of `args`
    // (BufferUsage::Indirect, in ResourceState::IndirectArgument; offset a multiple of 4). Core in both
    // APIs: Vulkan vkCmdDispatchIndirect, D3D12 ExecuteIndirect with a Dispatch command signature.
    virtual void dispatchIndirect(const BufferHandle& args, uint64_t offset = 0) = 0;

    // Rasterization (dynamic rendering; attachments must be in RenderTarget / DepthWrite).
    virtual void beginRendering(const RenderingDesc& desc) = 0;
    virtual void endRendering() = 0;
    virtual void setGraphicsPipeline(const GraphicsPipelineHandle& pipeline) = 0;
    virtual void setViewport(float x, float y, float width, float height) = 0;   // also sets the scissor
    virtual void setVertexBuffer(uint32_t slot, const BufferHandle& buffer, uint64_t offset = 0) = 0;
    virtual void setIndexBuffer(const BufferHandle& buffer, uint64_t offset = 0) = 0;   // uint32 indices
    virtual void draw(uint32_t vertexCount, uint32_t instanceCount = 1, uint32_t firstVertex = 0,
                      uint32_t firstInstance = 0) = 0;
    virtual void drawIndexed(uint32_t indexCount, uint32_t instanceCount = 1, uint32_t firstIndex = 0,
                             int32_t vertexOffset = 0, uint32_t firstInstance = 0) = 0;

    // Ray tracing.
    virtual void setRayTracingState(const StateObjectHandle& stateObject, const ShaderTableHandle& table) = 0;
    virtual void dispatchRays(uint32_t width, uint32_t height = 1, uint32_t depth = 1) = 0;
    // As dispatchRays, with the grid read by the GPU: three uint32 (width, height, depth) at `offset`
    // of `args` (BufferUsage::Indirect, in ResourceState::IndirectArgument; offset a multiple of 4).
    // Needs Capabilities::rayTracingIndirect. Vulkan: vkCmdTraceRaysIndirectKHR; D3D12: ExecuteIndirect
    // with a DispatchRays command signature (the backend adds the shader-table part of the argument).
    virtual void dispatchRaysIndirect(const BufferHandle& args, uint64_t offset = 0) = 0;
    // Bottom level: geometries come from the AS's own desc. `update` refits (needs AllowUpdate).
    virtual void buildBottomLevel(const AccelStructHandle& blas, bool update = false) = 0;
    // Top level from host instances (uploaded by the command list) or from a GPU buffer of InstanceDesc.
    virtual void buildTopLevel(const AccelStructHandle& tlas, std::span<const InstanceDesc> instances,
                               bool update = false) = 0;
    virtual void buildTopLevelFromBuffer(const AccelStructHandle& tlas, const BufferHandle& instances,
                                         uint64_t offset, uint32_t count, bool update = false) = 0;

    // Bindings of the pipeline set last (compute, graphics or ray tracing).
    virtual void setBindingSet(uint32_t index, const BindingSetHandle& set) = 0;
    virtual void setPushConstants(const void* data, uint32_t bytes) = 0;

    // Queries and markers. recordsTimestamps(): false for a host's list wrapped with allowTimestamps =
    // false (its timestamp calls record nothing, so a render graph creates no pool for it).
    virtual bool recordsTimestamps() const { return true; }
    virtual void resetTimestamps(const TimestampPoolHandle& pool, uint32_t first, uint32_t count) = 0;
    virtual void writeTimestamp(const TimestampPoolHandle& pool, uint32_t index) = 0;
    virtual void beginMarker(std::string_view name) = 0;
    virtual void endMarker() = 0;

    // VkCommandBuffer / ID3D12GraphicsCommandList4 (native_object.h).
    virtual NativeObject getNativeObject(NativeObjectType) const { return {}; }
};
using CommandListHandle = std::shared_ptr<ICommandList>;

}  // namespace caustics::rhi
