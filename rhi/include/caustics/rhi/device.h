#pragma once
// The device: creation with a run-time backend choice, capabilities, object factories, submission.
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string_view>
#include <optional>
#include <string>
#include <vector>

#include "caustics/rhi/command_list.h"
#include "caustics/rhi/result.h"
#include "caustics/rhi/log.h"

namespace caustics::rhi {

enum class Backend : uint8_t { Vulkan, D3D12 };
const char* backendName(Backend backend);
std::optional<Backend> parseBackend(std::string_view name);   // "vulkan" | "d3d12"

struct DeviceDesc {
    Backend backend = Backend::Vulkan;
    bool enableValidation = false;       // Vulkan validation layers (incl. synchronization) / D3D12 debug layer
    bool requireRayTracing = true;       // refuse a device without the ray-tracing pipeline + AS
    // Extra device features/extensions that must be present (names as the backend spells them,
    // e.g. "VK_EXT_mesh_shader"); a device lacking one is refused with its name in the error.
    std::vector<std::string> requiredExtensions;
    std::optional<uint32_t> adapterIndex;   // default: first adapter that satisfies the requirements
    // Called with every validation message; the default logs them. Tests count them.
    std::function<void(LogLevel, std::string_view)> validationCallback;
};

struct Capabilities {
    std::string adapterName;
    std::string driverName;
    bool rayTracingPipeline = false;
    bool accelerationStructure = false;
    bool rayQuery = false;
    bool shaderFloatAtomicAdd = false;   // atomicAdd on float storage buffers and images
    // 64-bit integer atomics on storage buffers (Vulkan shaderBufferInt64Atomics + shaderInt64; D3D12:
    // SM 6.6 + OPTIONS11 descriptor-heap int64 atomics, docs/d3d12.md): the fixed-point path's wide words.
    bool shaderBufferInt64Atomics = false;
    bool rayTracingIndirect = false;     // ICommandList::dispatchRaysIndirect
    uint32_t shaderGroupHandleSize = 32;
    uint32_t shaderGroupHandleAlignment = 32;
    uint32_t shaderGroupBaseAlignment = 64;
    uint32_t maxShaderGroupStride = 4096;
    uint32_t maxRayRecursionDepth = 1;
    uint32_t maxInstanceCount = 0;
    uint64_t maxPrimitiveCount = 0;      // triangles or AABBs in one bottom level (0 = unknown)
    double timestampPeriodNs = 1.0;      // nanoseconds per timestamp tick
    uint64_t minAccelStructScratchAlignment = 256;
    // Limits a host checks before sizing its frame (0 = unknown): texture width/height, the largest
    // device-local memory heap, and the largest single allocation (Vulkan maxMemoryAllocationSize).
    uint32_t maxTextureDimension2D = 0;
    uint64_t deviceMemoryBytes = 0;
    uint64_t maxAllocationBytes = 0;
};

class IDevice {
public:
    virtual ~IDevice() = default;
    virtual Backend backend() const = 0;
    virtual const Capabilities& capabilities() const = 0;
    // VkInstance, VkPhysicalDevice, VkDevice, VkQueue / ID3D12Device5, ID3D12CommandQueue (native_object.h).
    virtual NativeObject getNativeObject(NativeObjectType) const { return {}; }

    virtual Result<BufferHandle> createBuffer(const BufferDesc& desc) = 0;
    virtual Result<TextureHandle> createTexture(const TextureDesc& desc) = 0;
    virtual Result<SamplerHandle> createSampler(const SamplerDesc& desc) = 0;
    virtual Result<HeapHandle> createHeap(const HeapDesc& desc) = 0;
    virtual MemoryRequirements memoryRequirements(const TextureDesc& desc) = 0;
    virtual MemoryRequirements memoryRequirements(const BufferDesc& desc) = 0;
    // Places a virtual resource in a heap; resources placed over each other alias.
    virtual Status bindMemory(const TextureHandle& texture, const HeapHandle& heap, uint64_t offset) = 0;
    virtual Status bindMemory(const BufferHandle& buffer, const HeapHandle& heap, uint64_t offset) = 0;

    virtual Result<BindingLayoutHandle> createBindingLayout(const BindingLayoutDesc& desc) = 0;
    virtual Result<BindingSetHandle> createBindingSet(const BindingSetDesc& desc, const BindingLayoutHandle& layout) = 0;

    virtual Result<ComputePipelineHandle> createComputePipeline(const ComputePipelineDesc& desc) = 0;
    virtual Result<GraphicsPipelineHandle> createGraphicsPipeline(const GraphicsPipelineDesc& desc) = 0;

    virtual Result<AccelStructHandle> createAccelStruct(const AccelStructDesc& desc) = 0;
    // Builds a compacted copy of a built bottom level (built with AllowCompaction); waits for the GPU.
    virtual Result<AccelStructHandle> compactAccelStruct(const AccelStructHandle& built) = 0;
    virtual Result<StateObjectHandle> createStateObject(const StateObjectDesc& desc) = 0;
    virtual Result<ShaderTableHandle> createShaderTable(const ShaderTableDesc& desc) = 0;

    virtual Result<TimestampPoolHandle> createTimestampPool(uint32_t count) = 0;
    // Nanoseconds since an arbitrary origin; std::nullopt where a result is not yet available.
    virtual std::vector<std::optional<double>> readTimestamps(const TimestampPoolHandle& pool, uint32_t first,
                                                              uint32_t count) = 0;

    virtual Result<CommandListHandle> createCommandList() = 0;
    // Submits recorded lists in order; returns a fence value that waitForFence accepts.
    virtual Result<uint64_t> submit(std::span<const CommandListHandle> lists) = 0;
    Result<uint64_t> submit(const CommandListHandle& list) { return submit(std::span(&list, 1)); }
    virtual Status waitForFence(uint64_t value) = 0;
    virtual Status waitIdle() = 0;
    // Copies a host-visible buffer's bytes; a convenience for tests and readbacks.
    virtual Status readBuffer(const BufferHandle& buffer, void* dst, uint64_t bytes, uint64_t offset = 0) = 0;
};
using DeviceHandle = std::shared_ptr<IDevice>;

// Creates a device of the requested backend. Errors name what is missing (an extension, a feature,
// a runtime library), never crash.
Result<DeviceHandle> createDevice(const DeviceDesc& desc);

}  // namespace caustics::rhi
