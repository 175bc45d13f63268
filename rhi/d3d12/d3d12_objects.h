#pragma once
// The backend's implementations of the RHI object interfaces: plain holders of D3D12 objects.
#include <array>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "d3d12_headers.h"
#include "deferred_release_queue.h"
#include "descriptor_heaps.h"
#include "graphics_pipeline_desc.h"
#include "root_signature_layout.h"
#include "caustics/rhi/rhi.h"
#include "shader_table_image.h"

namespace caustics::rhi::d3d12 {

// Hands an object's D3D12 objects to its device's deferred releases (deferred_release_queue.h), so
// none is freed while the GPU may still use it; without a queue they are released at once.
template <typename... T>
void retireToQueue(const std::shared_ptr<DeferredReleaseQueue>& queue, ComPtr<T>&... objects) {
    if (!queue) return;
    (queue->retire(objects ? std::make_shared<ComPtr<T>>(std::move(objects)) : nullptr), ...);
}

class Buffer final : public IBuffer {
public:
    ~Buffer() override { retireToQueue(releases, resource); }
    BufferDesc desc_;
    std::shared_ptr<DeferredReleaseQueue> releases;
    ComPtr<ID3D12Resource> resource;
    void* mapped = nullptr;
    D3D12_RESOURCE_STATES state = D3D12_RESOURCE_STATE_COMMON;   // last state a barrier left it in
    const BufferDesc& desc() const override { return desc_; }
    uint64_t deviceAddress() const override { return resource ? resource->GetGPUVirtualAddress() : 0; }
    void* mappedData() override { return mapped; }
    NativeObject getNativeObject(NativeObjectType type) const override {
        return type == NativeObjectType::D3D12Resource ? NativeObject::from(resource.get()) : NativeObject();
    }
};

class Texture final : public ITexture {
public:
    ~Texture() override { retireToQueue(releases, resource); }
    TextureDesc desc_;
    std::shared_ptr<DeferredReleaseQueue> releases;
    ComPtr<ID3D12Resource> resource;
    D3D12_RESOURCE_STATES state = D3D12_RESOURCE_STATE_COMMON;
    const TextureDesc& desc() const override { return desc_; }
    NativeObject getNativeObject(NativeObjectType type) const override {
        return type == NativeObjectType::D3D12Resource ? NativeObject::from(resource.get()) : NativeObject();
    }
};

class Sampler final : public ISampler {
public:
    SamplerDesc desc_;
    const SamplerDesc& desc() const override { return desc_; }
};

class Heap final : public IHeap {
public:
    ~Heap() override { retireToQueue(releases, heap); }
    HeapDesc desc_;
    std::shared_ptr<DeferredReleaseQueue> releases;
    ComPtr<ID3D12Heap> heap;
    const HeapDesc& desc() const override { return desc_; }
};

class BindingLayout final : public IBindingLayout {
public:
    BindingLayoutDesc desc_;
    DescriptorTableLayout table;
    const BindingLayoutDesc& desc() const override { return desc_; }
};

class BindingSet final : public IBindingSet {
public:
    ~BindingSet() override;
    BindingSetDesc desc_;
    BindingLayoutHandle layout_;
    CpuDescriptorHeap* resourceHeap = nullptr;
    CpuDescriptorHeap* samplerHeap = nullptr;
    DescriptorRange resources, samplers;   // staging ranges, copied to the ring at bind time
    const BindingSetDesc& desc() const override { return desc_; }
    const BindingLayoutHandle& layout() const override { return layout_; }
};

// What every pipeline kind shares: a root signature and where its parameters are.
struct RootBinding {
    ComPtr<ID3D12RootSignature> rootSignature;
    RootSignatureLayout layout;
};

class ComputePipeline final : public IComputePipeline {
public:
    ~ComputePipeline() override { retireToQueue(releases, pso, root.rootSignature); }
    ComputePipelineDesc desc_;
    std::shared_ptr<DeferredReleaseQueue> releases;
    RootBinding root;
    ComPtr<ID3D12PipelineState> pso;
    const ComputePipelineDesc& desc() const override { return desc_; }
};

class GraphicsPipeline final : public IGraphicsPipeline {
public:
    ~GraphicsPipeline() override { retireToQueue(releases, pso, root.rootSignature); }
    GraphicsPipelineDesc desc_;
    std::shared_ptr<DeferredReleaseQueue> releases;
    RootBinding root;
    ComPtr<ID3D12PipelineState> pso;
    D3D_PRIMITIVE_TOPOLOGY topology = D3D_PRIMITIVE_TOPOLOGY_TRIANGLELIST;
    std::array<uint32_t, kMaxVertexBufferSlots> strides{};   // per vertex-buffer slot
    const GraphicsPipelineDesc& desc() const override { return desc_; }
};

class AccelStruct final : public IAccelStruct {
public:
    ~AccelStruct() override { retireToQueue(releases, storage, scratch, instances); }
    AccelStructDesc desc_;
    std::shared_ptr<DeferredReleaseQueue> releases;
    ComPtr<ID3D12Resource> storage;    // in RAYTRACING_ACCELERATION_STRUCTURE for its whole life
    ComPtr<ID3D12Resource> scratch;    // sized for max(build, update)
    ComPtr<ID3D12Resource> instances;  // top level: upload buffer for host instances
    void* instancesMapped = nullptr;
    uint64_t storageSize = 0;
    uint64_t storageOffset = 0;   // non-zero only for a host's structure inside a larger buffer
    const AccelStructDesc& desc() const override { return desc_; }
    uint64_t deviceAddress() const override { return storage ? storage->GetGPUVirtualAddress() + storageOffset : 0; }
    NativeObject getNativeObject(NativeObjectType type) const override {
        return type == NativeObjectType::D3D12Resource ? NativeObject::from(storage.get()) : NativeObject();
    }
    uint64_t storageBytes() const override { return storageSize; }
};

class StateObject final : public IStateObject {
public:
    ~StateObject() override { retireToQueue(releases, stateObject, localRootSignature, root.rootSignature); }
    StateObjectDesc desc_;
    std::shared_ptr<DeferredReleaseQueue> releases;
    RootBinding root;
    ComPtr<ID3D12RootSignature> localRootSignature;
    ComPtr<ID3D12StateObject> stateObject;
    std::unordered_map<std::string, std::vector<uint8_t>> identifiers;
    const StateObjectDesc& desc() const override { return desc_; }
    std::vector<uint8_t> shaderIdentifier(const std::string& exportName) const override {
        auto it = identifiers.find(exportName);
        return it == identifiers.end() ? std::vector<uint8_t>{} : it->second;
    }
};

class ShaderTable final : public IShaderTable {
public:
    ~ShaderTable() override { retireToQueue(releases, buffer); }
    ShaderTableDesc desc_;
    std::shared_ptr<DeferredReleaseQueue> releases;
    ShaderTableLayout layout;
    ComPtr<ID3D12Resource> buffer;   // upload heap, GENERIC_READ
    const ShaderTableDesc& desc() const override { return desc_; }
};

class TimestampPool final : public ITimestampPool {
public:
    ~TimestampPool() override { retireToQueue(releases, heap, readback); }
    std::shared_ptr<DeferredReleaseQueue> releases;
    ComPtr<ID3D12QueryHeap> heap;
    ComPtr<ID3D12Resource> readback;   // resolved ticks
    void* mapped = nullptr;
    uint32_t count = 0;
    std::vector<uint8_t> written;      // resolved at least once since reset
    uint32_t capacity() const override { return count; }
};

class Device;
// Root signature (layout + created object) for a pipeline's bindings (d3d12_pipelines.cpp).
Result<RootBinding> makeRootBinding(Device& device, const PipelineBindings& bindings, RootSignatureKind kind,
                                    const std::string& name);

// Creates a committed buffer (helper shared by several files).
Result<ComPtr<ID3D12Resource>> createCommittedBuffer(ID3D12Device* device, uint64_t bytes, D3D12_HEAP_TYPE heap,
                                                     D3D12_RESOURCE_FLAGS flags, D3D12_RESOURCE_STATES state,
                                                     const std::string& name);
void setDebugName(ID3D12Object* object, const std::string& name);

}  // namespace caustics::rhi::d3d12
