#pragma once
// The D3D12 device: owns the runtime libraries, the ID3D12Device5, the direct queue and its fence,
// and the descriptor heaps (CPU staging for binding sets, a shader-visible ring per command list).
#include <memory>
#include <mutex>

#include "d3d12_headers.h"
#include "deferred_release_queue.h"
#include "descriptor_heaps.h"
#include "caustics/rhi/device.h"
#include "runtime_library.h"
#include "shader_compiler.h"

namespace caustics::rhi::d3d12 {

struct RuntimeLibraries {
    RuntimeLibrary d3d12;
    RuntimeLibrary dxcore;       // optional: adapter choice
    RuntimeLibrary dxcompiler;
};

// d3d12, dxcompiler (both required) and dxcore (optional), loaded at run time (d3d12_device_factory.cpp).
Result<RuntimeLibraries> loadRuntimeLibraries();

class Device final : public IDevice, public std::enable_shared_from_this<Device> {
public:
    static Result<DeviceHandle> create(const DeviceDesc& desc, RuntimeLibraries libs);
    // Over a host engine's device and queue (d3d12_device_wrap.cpp, d3d12_interop.h).
    static Result<DeviceHandle> wrap(ID3D12Device5* device, ID3D12CommandQueue* queue, const std::string& name,
                                     RuntimeLibraries libs);
    ~Device() override;

    Backend backend() const override { return Backend::D3D12; }
    const Capabilities& capabilities() const override { return caps_; }
    NativeObject getNativeObject(NativeObjectType type) const override;

    Result<BufferHandle> createBuffer(const BufferDesc& desc) override;
    Result<TextureHandle> createTexture(const TextureDesc& desc) override;
    Result<SamplerHandle> createSampler(const SamplerDesc& desc) override;
    Result<HeapHandle> createHeap(const HeapDesc& desc) override;
    MemoryRequirements memoryRequirements(const TextureDesc& desc) override;
    MemoryRequirements memoryRequirements(const BufferDesc& desc) override;
    Status bindMemory(const TextureHandle& texture, const HeapHandle& heap, uint64_t offset) override;
    Status bindMemory(const BufferHandle& buffer, const HeapHandle& heap, uint64_t offset) override;

    Result<BindingLayoutHandle> createBindingLayout(const BindingLayoutDesc& desc) override;
    Result<BindingSetHandle> createBindingSet(const BindingSetDesc& desc, const BindingLayoutHandle& layout) override;
    Result<ComputePipelineHandle> createComputePipeline(const ComputePipelineDesc& desc) override;
    Result<GraphicsPipelineHandle> createGraphicsPipeline(const GraphicsPipelineDesc& desc) override;

    Result<AccelStructHandle> createAccelStruct(const AccelStructDesc& desc) override;
    Result<AccelStructHandle> compactAccelStruct(const AccelStructHandle& built) override;
    Result<StateObjectHandle> createStateObject(const StateObjectDesc& desc) override;
    Result<ShaderTableHandle> createShaderTable(const ShaderTableDesc& desc) override;

    Result<TimestampPoolHandle> createTimestampPool(uint32_t count) override;
    std::vector<std::optional<double>> readTimestamps(const TimestampPoolHandle& pool, uint32_t first,
                                                      uint32_t count) override;

    Result<CommandListHandle> createCommandList() override;
    Result<uint64_t> submit(std::span<const CommandListHandle> lists) override;
    Status waitForFence(uint64_t value) override;
    Status waitIdle() override;
    Status readBuffer(const BufferHandle& buffer, void* dst, uint64_t bytes, uint64_t offset = 0) override;

    // A fence value for a host's own ExecuteCommandLists to signal (d3d12_device_wrap.cpp):
    // waitForFence then waits for the host's submission like for ours.
    std::pair<ID3D12Fence*, uint64_t> reserveHostSignal();

    // For the backend's own objects.
    ID3D12Device5* d3d() const { return device_.get(); }
    CpuDescriptorHeap& cpuResourceDescriptors() { return *cpuResources_; }
    CpuDescriptorHeap& cpuSamplerDescriptors() { return *cpuSamplers_; }
    ShaderCompiler& shaderCompiler() { return *compiler_; }
    // Every object this device creates retires its D3D12 objects here (deferred_release_queue.h).
    const std::shared_ptr<DeferredReleaseQueue>& releaseQueue() const { return releases_; }
    Result<ComPtr<ID3D12RootSignature>> createRootSignature(const struct RootSignatureLayout& layout,
                                                            const std::string& name);
    // Bytecode for DXIL as is, HLSL compiled with dxcompiler, SPIR-V refused.
    Result<std::vector<uint8_t>> bytecodeFor(const ShaderCode& code, const std::string& entryPoint, ShaderStage stage,
                                             bool library);
    // Runs a one-off command list to completion (compaction, uploads outside a frame).
    Status runImmediate(const std::function<void(ID3D12GraphicsCommandList4*)>& record);

private:
    Device() = default;
    Status init(const DeviceDesc& desc);
    Status finishInit();

    RuntimeLibraries libs_;
    Capabilities caps_;
    uint32_t shaderModel_ = 0;   // the device's highest (D3D_SHADER_MODEL): picks the HLSL profiles
    bool debugLayer_ = false;
    ComPtr<ID3D12Device5> device_;
    ComPtr<ID3D12CommandQueue> queue_;
    ComPtr<ID3D12Fence> fence_;
    uint64_t nextFenceValue_ = 1;
    std::mutex submitMutex_;
    std::unique_ptr<CpuDescriptorHeap> cpuResources_, cpuSamplers_;
    std::unique_ptr<ShaderCompiler> compiler_;
    std::shared_ptr<DeferredReleaseQueue> releases_;
    PFN_D3D12_SERIALIZE_VERSIONED_ROOT_SIGNATURE serializeRootSignature_ = nullptr;
};

}  // namespace caustics::rhi::d3d12
