#pragma once
// Embedding the module in a D3D12 engine: wrap the host's ID3D12Device5 and direct queue, import its
// resources with their current D3D12_RESOURCE_STATES, and record into its command lists. The D3D12
// types are forward-declared and enums passed as their integer values, so this header needs no
// d3d12.h. Contract (ownership, fences, threading): docs/embedding.md "Device and resources".
#include <cstdint>
#include <string>
#include <string_view>

#include "caustics/rhi/device.h"

struct ID3D12Device5;
struct ID3D12CommandQueue;
struct ID3D12Resource;
struct ID3D12GraphicsCommandList4;
struct ID3D12Fence;
struct ID3D12DescriptorHeap;

namespace caustics::rhi {

// ---- The host's device -------------------------------------------------------------------------

struct D3D12DeviceImport {
    ID3D12Device5* device = nullptr;       // a reference is held while the wrapped device lives
    ID3D12CommandQueue* queue = nullptr;   // D3D12_COMMAND_LIST_TYPE_DIRECT; IDevice::submit uses it
    bool requireRayTracing = true;
    std::string debugName = "host device";
};

// What the module needs from ID3D12Device::CheckFeatureSupport, as plain values (device-free checks).
struct D3D12FeatureReport {
    uint32_t raytracingTier = 0;       // D3D12_FEATURE_DATA_D3D12_OPTIONS5::RaytracingTier (10 = TIER_1_0)
    uint32_t highestShaderModel = 0;   // D3D12_FEATURE_DATA_SHADER_MODEL::HighestShaderModel (0x63 = 6.3)
    // D3D12_FEATURE_DATA_D3D12_OPTIONS11: 64-bit atomics on UAVs reached through a descriptor heap, which
    // is how the backend binds the caustic radiance buffers (SM 6.6 alone promises them only on root UAVs).
    bool atomicInt64OnDescriptorHeapResource = false;
    // D3D12_FEATURE_DATA_D3D12_OPTIONS::TypedUAVLoadAdditionalFormats: loads from RGBA16F and RGBA32F
    // storage textures (the second type's guide fill and the types' combine read what they write); a set
    // feature of D3D12 hardware, not a guarantee (only the R32 formats are).
    bool typedUavLoadAdditionalFormats = false;
};

// ok, or ONE error naming every missing feature (e.g. "DXR: RaytracingTier 1.0 (device reports
// NOT_SUPPORTED); shader model 6.3 (device reports 6.0)"); the caustic passes (requireRayTracing) also
// need typed UAV loads of the additional formats. Device-free.
Status checkD3D12DeviceRequirements(const D3D12FeatureReport& report, bool requireRayTracing,
                                    std::string_view deviceName);

// Wraps the host's device and queue: creates only the module's fence, descriptor heaps and its own
// resources. Loads d3d12 (for root-signature serialization) and dxcompiler at run time; refuses a
// device that fails checkD3D12DeviceRequirements.
Result<DeviceHandle> wrapD3D12Device(const D3D12DeviceImport& desc);

// ---- The host's resources ----------------------------------------------------------------------

// The RHI state for D3D12_RESOURCE_STATES bits (RenderGraph::importTexture's current/final states),
// or an error naming bits the RHI has no state for. Device-free.
Result<ResourceState> resourceStateFromD3D12(uint32_t d3d12ResourceStates);

// Format and usage of a host texture are read from ID3D12Resource::GetDesc(); each of `uses` must be
// allowed by its flags (Storage: ALLOW_UNORDERED_ACCESS, RenderTarget: ALLOW_RENDER_TARGET,
// DepthStencil: ALLOW_DEPTH_STENCIL, Sampled: not DENY_SHADER_RESOURCE), otherwise the import fails
// naming the texture and the problem.
struct D3D12TextureImport {
    ID3D12Resource* resource = nullptr;   // a reference is held, the resource is never released early
    uint32_t currentStates = 0;           // D3D12_RESOURCE_STATES the resource is in now
    TextureUsage uses = TextureUsage::Sampled;
    bool cube = false;
    std::string debugName;
};
Result<TextureHandle> importD3D12Texture(IDevice& device, const D3D12TextureImport& desc);

// Device-free part of importD3D12Texture: the RHI texture desc for a resource desc given as values,
// or the error naming the texture and what it cannot do.
struct D3D12TextureFacts {
    uint32_t dimension = 0;    // D3D12_RESOURCE_DIMENSION (3 = TEXTURE2D)
    uint32_t dxgiFormat = 0;   // DXGI_FORMAT
    uint64_t width = 0;
    uint32_t height = 0;
    uint32_t arrayLayers = 1, mipLevels = 1;
    uint32_t flags = 0;        // D3D12_RESOURCE_FLAGS
};
Result<TextureDesc> textureDescFromD3D12(const D3D12TextureFacts& facts, TextureUsage uses, bool cube,
                                         const std::string& debugName);

struct D3D12BufferImport {
    ID3D12Resource* resource = nullptr;
    uint32_t currentStates = 0;
    BufferUsage uses = BufferUsage::Storage;   // Storage needs ALLOW_UNORDERED_ACCESS for writes
    uint32_t structStride = 0;
    std::string debugName;
};
Result<BufferHandle> importD3D12Buffer(IDevice& device, const D3D12BufferImport& desc);

// The host's acceleration structure: a buffer in RAYTRACING_ACCELERATION_STRUCTURE state.
struct D3D12AccelStructImport {
    ID3D12Resource* storage = nullptr;
    uint64_t offset = 0;   // of the structure in `storage` (its GPU VA is storage VA + offset)
    bool isTopLevel = true;
    std::string debugName;
};
Result<AccelStructHandle> importD3D12AccelStruct(IDevice& device, const D3D12AccelStructImport& desc);

// ---- The host's command list -------------------------------------------------------------------

struct D3D12CommandListImport {
    ID3D12GraphicsCommandList4* commandList = nullptr;   // open (Reset by the host), DIRECT type
    bool allowTimestamps = true;   // false: no queries recorded, per-pass times stay empty
    std::string debugName = "host command list";
    // The shader-visible heaps the host has set on the list (CBV_SRV_UAV, SAMPLER; either may be null).
    // D3D12 cannot read them back from a list, so the host names them: the module sets its own heaps
    // at the start of each of its passes and sets these again at the end of each, so the host's
    // descriptor tables are valid again after the graph (and after every pass, for a host pass between).
    ID3D12DescriptorHeap* hostDescriptorHeaps[2] = {nullptr, nullptr};
};
// An ICommandList that records into the host's list. begin()/end() record nothing (the host resets,
// closes and executes it). The module's shader-visible descriptor heaps are set on it for each of its
// passes (the render graph's beginMarker) and the host's `hostDescriptorHeaps` restored after each
// (endMarker); without them the module's stay set after the graph. A host's root signature and
// tables are never restored: set them again after the graph, as after any SetDescriptorHeaps.
Result<CommandListHandle> wrapD3D12CommandList(IDevice& device, const D3D12CommandListImport& desc);

// Before the host closes and executes a wrapped list: fails with the first recording error, else
// gives a fence value for the host to signal on its queue right after ExecuteCommandLists
// (queue->Signal(fence, value)), so IDevice::waitForFence covers the host's submission.
struct D3D12SubmitSignal {
    ID3D12Fence* fence = nullptr;
    uint64_t value = 0;
};
Result<D3D12SubmitSignal> d3d12SubmitSignal(IDevice& device, ICommandList& wrapped);

}  // namespace caustics::rhi
