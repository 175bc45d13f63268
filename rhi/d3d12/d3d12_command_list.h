#pragma once
// The D3D12 command list: legacy resource barriers (resource_states.h), copies, compute,
// rasterization, DispatchRays, AS builds, bindings through the shader-visible descriptor ring,
// timestamps and markers. Split over d3d12_command_list.cpp (core, compute, ray tracing, submit),
// d3d12_command_list_graphics.cpp and d3d12_command_list_copy.cpp (textures, clears).
#include <array>
#include <cstring>
#include <functional>
#include <string>

#include "accel_struct_inputs.h"
#include "d3d12_device.h"
#include "d3d12_objects.h"
#include "debug_marker.h"
#include "resource_states.h"

namespace caustics::rhi::d3d12 {

constexpr uint32_t kRingResources = 16384, kRingSamplers = 1024;
// Per recording: render-target / depth views of beginRendering and clears, CPU UAVs of UAV clears.
constexpr uint32_t kRecordingRtvs = 256, kRecordingDsvs = 64, kRecordingCpuUavs = 256;

class CommandList final : public ICommandList {
public:
    // A list destroyed while its last submission runs keeps the allocator's memory, the
    // shader-visible descriptor rings and its upload buffers until the GPU is done.
    ~CommandList() override {
        if (!releases) return;
        retireToQueue(releases, list, allocator, dispatchRaysSignature, dispatchSignature);
        releases->retire(std::shared_ptr<GpuDescriptorRing>(std::move(resourceRing)));
        releases->retire(std::shared_ptr<GpuDescriptorRing>(std::move(samplerRing)));
        for (auto& upload : keepAlive) releases->retire(std::move(upload));
    }
    Device* device = nullptr;
    std::shared_ptr<DeferredReleaseQueue> releases;
    ComPtr<ID3D12CommandAllocator> allocator;
    ComPtr<ID3D12GraphicsCommandList4> list;
    std::unique_ptr<GpuDescriptorRing> resourceRing, samplerRing;
    std::vector<std::shared_ptr<void>> keepAlive;   // upload buffers used by this recording
    const RootBinding* root = nullptr;
    bool computeBindPoint = true;
    // Rasterization: per-recording CPU descriptors (RTV/DSV are read when recorded, so a linear
    // allocator reset at begin() suffices; the CPU UAVs feed ClearUnorderedAccessView*).
    std::unique_ptr<CpuDescriptorHeap> rtvHeap, dsvHeap, uavCpuHeap;
    DescriptorRange rtvRange, dsvRange, uavCpuRange;
    uint32_t rtvUsed = 0, dsvUsed = 0, uavCpuUsed = 0;
    GraphicsPipeline* graphics = nullptr;
    std::array<D3D12_VERTEX_BUFFER_VIEW, kMaxVertexBufferSlots> vertexBuffers{};
    uint32_t vertexBufferSlots = 0;   // 1 + highest slot set
    ShaderTable* table = nullptr;
    Status firstError = okStatus();

    // Shader-visible rings and per-recording CPU heaps (our lists and wrapped host lists alike).
    Status createDescriptorStorage(ID3D12Device* d3d);

    void fail(Error e) {
        log(LogLevel::Error, e.message);
        if (firstError.ok()) firstError = std::move(e);
    }

    // A host's list (d3d12_interop_command_list.cpp) has no allocator: the host resets and closes it.
    bool timestampsAllowed = true;
    // A host's list: the heaps it had set (D3D12CommandListImport::hostDescriptorHeaps), restored at
    // every outermost endMarker (the end of a graph pass); ours are set again at the next beginMarker.
    ID3D12DescriptorHeap* hostHeaps[2] = {nullptr, nullptr};
    uint32_t markerDepth = 0;

    void setModuleHeaps() {
        ID3D12DescriptorHeap* heaps[] = {resourceRing->heap(), samplerRing->heap()};
        list->SetDescriptorHeaps(2, heaps);
        // A new heap invalidates the bound descriptor tables: bind root and tables again.
        root = nullptr;
        graphics = nullptr;
    }
    void restoreHostHeaps() {
        ID3D12DescriptorHeap* heaps[2];
        UINT count = 0;
        for (ID3D12DescriptorHeap* h : hostHeaps)
            if (h) heaps[count++] = h;
        if (count) list->SetDescriptorHeaps(count, heaps);
    }

    void begin() override {
        if (allocator) {
            allocator->Reset();
            list->Reset(allocator.get(), nullptr);
        }
        resourceRing->reset();
        samplerRing->reset();
        keepAlive.clear();
        root = nullptr;
        table = nullptr;
        graphics = nullptr;
        rtvUsed = dsvUsed = uavCpuUsed = 0;
        vertexBuffers = {};
        vertexBufferSlots = 0;
        firstError = okStatus();
        markerDepth = 0;
        setModuleHeaps();
    }
    void end() override {
        if (allocator) list->Close();
    }

    void barriers(std::span<const TextureBarrier> textures, std::span<const BufferBarrier> buffers,
                  std::span<const AccelStructBarrier> accelStructs) override {
        std::vector<D3D12_RESOURCE_BARRIER> out;
        auto emit = [&](ID3D12Resource* r, const BarrierPlan& p, D3D12_RESOURCE_STATES& tracked) {
            if (p.aliasing) {
                D3D12_RESOURCE_BARRIER b{};
                b.Type = D3D12_RESOURCE_BARRIER_TYPE_ALIASING;
                b.Aliasing = {nullptr, r};   // null "before": any resource placed over the same memory
                out.push_back(b);
            }
            if (p.transition) {
                D3D12_RESOURCE_BARRIER b{};
                b.Type = D3D12_RESOURCE_BARRIER_TYPE_TRANSITION;
                b.Transition = {r, D3D12_RESOURCE_BARRIER_ALL_SUBRESOURCES, p.before, p.after};
                out.push_back(b);
                tracked = p.after;
            }
            if (p.uav) {
                D3D12_RESOURCE_BARRIER b{};
                b.Type = D3D12_RESOURCE_BARRIER_TYPE_UAV;
                b.UAV.pResource = r;
                out.push_back(b);
            }
        };
        for (const TextureBarrier& t : textures) {
            auto* tex = static_cast<Texture*>(t.texture.get());
            emit(tex->resource.get(), planBarrier(t.before, t.after, tex->state, t.aliasing), tex->state);
        }
        for (const BufferBarrier& bb : buffers) {
            auto* buf = static_cast<Buffer*>(bb.buffer.get());
            if (buf->desc_.memory != MemoryType::DeviceLocal) continue;   // upload/readback states are fixed
            if (hasAny(buf->desc_.usage, BufferUsage::AccelStructStorage)) {
                D3D12_RESOURCE_STATES fixed = buf->state;
                emit(buf->resource.get(), planAccelStructBarrier(bb.before, bb.after), fixed);
                continue;
            }
            emit(buf->resource.get(), planBarrier(bb.before, bb.after, buf->state, bb.aliasing), buf->state);
        }
        for (const AccelStructBarrier& a : accelStructs) {
            auto* as = static_cast<AccelStruct*>(a.accelStruct.get());
            D3D12_RESOURCE_STATES fixed = D3D12_RESOURCE_STATE_RAYTRACING_ACCELERATION_STRUCTURE;
            emit(as->storage.get(), planAccelStructBarrier(a.before, a.after), fixed);
        }
        if (!out.empty()) list->ResourceBarrier(UINT(out.size()), out.data());
    }

    // Host data goes through a per-recording upload buffer, copied on the GPU timeline.
    ComPtr<ID3D12Resource> upload(const void* data, uint64_t bytes) {
        return uploadWith(bytes, [&](uint8_t* mapped) { std::memcpy(mapped, data, bytes); });
    }
    // An upload buffer of `bytes` filled by `fill` through its mapping, kept alive by this recording.
    ComPtr<ID3D12Resource> uploadWith(uint64_t bytes, const std::function<void(uint8_t*)>& fill) {
        auto r = createCommittedBuffer(device->d3d(), bytes, D3D12_HEAP_TYPE_UPLOAD, D3D12_RESOURCE_FLAG_NONE,
                                       D3D12_RESOURCE_STATE_GENERIC_READ, "upload");
        if (!r) { fail(r.error()); return {}; }
        void* mapped = nullptr;
        r.value()->Map(0, nullptr, &mapped);
        fill(static_cast<uint8_t*>(mapped));
        r.value()->Unmap(0, nullptr);
        keep(r.value());
        return r.value();
    }
    void keep(const ComPtr<ID3D12Resource>& resource) {
        resource->AddRef();
        keepAlive.emplace_back(resource.get(), [](void* p) { static_cast<ID3D12Resource*>(p)->Release(); });
    }

    void writeBuffer(const BufferHandle& dst, const void* data, uint64_t bytes, uint64_t dstOffset) override {
        auto* b = static_cast<Buffer*>(dst.get());
        if (b->mapped) { std::memcpy(static_cast<uint8_t*>(b->mapped) + dstOffset, data, bytes); return; }
        if (auto src = upload(data, bytes)) list->CopyBufferRegion(b->resource.get(), dstOffset, src.get(), 0, bytes);
    }
    void copyBuffer(const BufferHandle& dst, uint64_t dstOffset, const BufferHandle& src, uint64_t srcOffset,
                    uint64_t bytes) override {
        list->CopyBufferRegion(static_cast<Buffer*>(dst.get())->resource.get(), dstOffset,
                               static_cast<Buffer*>(src.get())->resource.get(), srcOffset, bytes);
    }
    void fillBuffer(const BufferHandle& dst, uint32_t value, uint64_t offset, uint64_t bytes) override {
        auto* b = static_cast<Buffer*>(dst.get());
        if (bytes == ~0ull) bytes = b->desc_.byteSize - offset;
        std::vector<uint32_t> pattern(bytes / 4, value);
        writeBuffer(dst, pattern.data(), pattern.size() * 4, offset);
    }
    // d3d12_command_list_copy.cpp
    void writeTexture(const TextureHandle& dst, uint32_t layer, uint32_t mip, const void* data, uint64_t bytes) override;
    void copyTextureToBuffer(const BufferHandle& dst, uint64_t dstOffset, const TextureHandle& src, uint32_t layer,
                             uint32_t mip) override;
    // d3d12_texture_to_texture_copy.cpp
    void copyTexture(const TextureHandle& dst, const TextureRegion& dstRegion, const TextureHandle& src,
                     const TextureRegion& srcRegion) override;
    void clearTextureFloat(const TextureHandle& texture, const float value[4]) override;
    void clearTextureUint(const TextureHandle& texture, const uint32_t value[4]) override;
    void clearTexture(Texture& texture, const float* floats, const uint32_t* uints);
    void clearByCopy(Texture& texture, const std::vector<uint8_t>& pixel);
    void copyPixelsToTexture(Texture& texture, uint32_t layer, uint32_t mip, const uint8_t* tight, uint64_t bytes);
    void transition(Texture& texture, D3D12_RESOURCE_STATES after);
    Result<D3D12_CPU_DESCRIPTOR_HANDLE> nextCpuDescriptor(CpuDescriptorHeap& heap, const DescriptorRange& range,
                                                          uint32_t& used, const char* what);

    void setComputePipeline(const ComputePipelineHandle& pipeline) override {
        auto* p = static_cast<ComputePipeline*>(pipeline.get());
        list->SetComputeRootSignature(p->root.rootSignature.get());
        list->SetPipelineState(p->pso.get());
        root = &p->root;
        computeBindPoint = true;
        graphics = nullptr;
    }
    void dispatch(uint32_t x, uint32_t y, uint32_t z) override { list->Dispatch(x, y, z); }
    // d3d12_dispatch_indirect.cpp
    void dispatchIndirect(const BufferHandle& args, uint64_t offset) override;
    ComPtr<ID3D12CommandSignature> dispatchSignature;   // made on first use

    // d3d12_command_list_graphics.cpp
    void beginRendering(const RenderingDesc& desc) override;
    void endRendering() override;
    void setGraphicsPipeline(const GraphicsPipelineHandle& pipeline) override;
    void setViewport(float x, float y, float width, float height) override;
    void setVertexBuffer(uint32_t slot, const BufferHandle& buffer, uint64_t offset) override;
    void setIndexBuffer(const BufferHandle& buffer, uint64_t offset) override;
    void draw(uint32_t vertexCount, uint32_t instanceCount, uint32_t firstVertex, uint32_t firstInstance) override;
    void drawIndexed(uint32_t indexCount, uint32_t instanceCount, uint32_t firstIndex, int32_t vertexOffset,
                     uint32_t firstInstance) override;
    bool flushDrawState(uint32_t baseVertex, uint32_t firstInstance);

    void setRayTracingState(const StateObjectHandle& stateObject, const ShaderTableHandle& shaderTable) override {
        auto* so = static_cast<StateObject*>(stateObject.get());
        list->SetComputeRootSignature(so->root.rootSignature.get());   // DXR uses the compute bind point
        list->SetPipelineState1(so->stateObject.get());
        root = &so->root;
        computeBindPoint = true;
        table = static_cast<ShaderTable*>(shaderTable.get());
    }
    void dispatchRays(uint32_t width, uint32_t height, uint32_t depth) override {
        if (!table) return fail(makeError("d3d12 dispatchRays: no shader table set"));
        D3D12_DISPATCH_RAYS_DESC d =
            makeDispatchRaysDesc(table->layout, table->buffer->GetGPUVirtualAddress(), width, height, depth);
        list->DispatchRays(&d);
    }

    // d3d12_dispatch_rays_indirect.cpp
    void dispatchRaysIndirect(const BufferHandle& args, uint64_t offset) override;
    ComPtr<ID3D12CommandSignature> dispatchRaysSignature;   // made on first use

    void buildBottomLevel(const AccelStructHandle& handle, bool update) override {
        auto* as = static_cast<AccelStruct*>(handle.get());
        BottomLevelInputs inputs;
        makeBottomLevelInputs(as->desc_, update, inputs);
        build(*as, inputs.inputs, update);
    }
    void buildTopLevel(const AccelStructHandle& handle, std::span<const InstanceDesc> instances, bool update) override {
        auto* as = static_cast<AccelStruct*>(handle.get());
        if (instances.size() > as->desc_.maxInstances)
            return fail(makeError("d3d12: too many instances for '" + as->desc_.debugName + "'"));
        // Host instances go through their own upload buffer so earlier builds in flight keep theirs.
        auto src = upload(instances.data(), std::max<uint64_t>(instances.size_bytes(), 1));
        if (!src) return;
        build(*as, makeTopLevelInputs(as->desc_, src->GetGPUVirtualAddress(), uint32_t(instances.size()), update),
              update);
    }
    void buildTopLevelFromBuffer(const AccelStructHandle& handle, const BufferHandle& instances, uint64_t offset,
                                 uint32_t count, bool update) override {
        auto* as = static_cast<AccelStruct*>(handle.get());
        build(*as, makeTopLevelInputs(as->desc_, instances->deviceAddress() + offset, count, update), update);
    }
    void build(AccelStruct& as, const D3D12_BUILD_RAYTRACING_ACCELERATION_STRUCTURE_INPUTS& inputs, bool update) {
        D3D12_BUILD_RAYTRACING_ACCELERATION_STRUCTURE_DESC d{};
        d.DestAccelerationStructureData = as.deviceAddress();
        d.Inputs = inputs;
        d.SourceAccelerationStructureData = update ? as.deviceAddress() : 0;   // in-place refit
        d.ScratchAccelerationStructureData = as.scratch->GetGPUVirtualAddress();
        list->BuildRaytracingAccelerationStructure(&d, 0, nullptr);
        // The scratch buffer is reused by the next build: order them (DXR spec: UAV barrier between builds).
        D3D12_RESOURCE_BARRIER b{};
        b.Type = D3D12_RESOURCE_BARRIER_TYPE_UAV;
        b.UAV.pResource = as.scratch.get();
        list->ResourceBarrier(1, &b);
    }

    void setBindingSet(uint32_t index, const BindingSetHandle& handle) override {
        if (!root || index >= root->layout.tables.size())
            return fail(makeError("d3d12 setBindingSet: no pipeline set, or it has no binding layout " + std::to_string(index)));
        auto* set = static_cast<BindingSet*>(handle.get());
        auto bindTable = [&](int32_t parameter, GpuDescriptorRing& ring, CpuDescriptorHeap& heap,
                             const DescriptorRange& range) {
            if (parameter < 0) return;
            auto gpu = ring.push(device->d3d(), heap.at(range.first), range.count);
            if (!gpu) return fail(gpu.error());
            if (computeBindPoint) list->SetComputeRootDescriptorTable(UINT(parameter), gpu.value());
            else list->SetGraphicsRootDescriptorTable(UINT(parameter), gpu.value());
        };
        bindTable(root->layout.resourceTableParameter[index], *resourceRing, device->cpuResourceDescriptors(), set->resources);
        bindTable(root->layout.samplerTableParameter[index], *samplerRing, device->cpuSamplerDescriptors(), set->samplers);
    }
    void setPushConstants(const void* data, uint32_t bytes) override {
        if (!root || root->layout.pushConstantParameter < 0)
            return fail(makeError("d3d12 setPushConstants: the pipeline declares no push constants"));
        if (computeBindPoint) list->SetComputeRoot32BitConstants(UINT(root->layout.pushConstantParameter), bytes / 4, data, 0);
        else list->SetGraphicsRoot32BitConstants(UINT(root->layout.pushConstantParameter), bytes / 4, data, 0);
    }

    bool recordsTimestamps() const override { return timestampsAllowed; }
    void resetTimestamps(const TimestampPoolHandle& pool, uint32_t first, uint32_t count) override {
        if (!timestampsAllowed) return;
        auto* p = static_cast<TimestampPool*>(pool.get());
        for (uint32_t i = first; i < first + count && i < p->count; ++i) p->written[i] = 0;
    }
    void writeTimestamp(const TimestampPoolHandle& pool, uint32_t index) override {
        if (!timestampsAllowed) return;
        auto* p = static_cast<TimestampPool*>(pool.get());
        list->EndQuery(p->heap.get(), D3D12_QUERY_TYPE_TIMESTAMP, index);
        list->ResolveQueryData(p->heap.get(), D3D12_QUERY_TYPE_TIMESTAMP, index, 1, p->readback.get(), uint64_t(index) * 8);
        p->written[index] = 1;
    }
    // PIX-free markers (debug_marker.h): metadata 0 + UTF-16 name, shown by PIX, RenderDoc and NSight.
    void beginMarker(std::string_view name) override {
        const std::u16string payload = markerPayload(name);
        list->BeginEvent(kMarkerMetadataUnicode, payload.data(), UINT(payload.size() * sizeof(char16_t)));
        if (!allocator && markerDepth++ == 0) setModuleHeaps();
    }
    void endMarker() override {
        list->EndEvent();
        if (!allocator && markerDepth > 0 && --markerDepth == 0) restoreHostHeaps();
    }
    NativeObject getNativeObject(NativeObjectType type) const override {
        return type == NativeObjectType::D3D12GraphicsCommandList ? NativeObject::from(list.get()) : NativeObject();
    }
};

}  // namespace caustics::rhi::d3d12
