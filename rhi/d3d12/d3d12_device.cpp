// Device creation (adapter choice, debug layer, DXR check), submission, fences, readback.
#include "d3d12_device.h"

#include <chrono>
#include <cstring>
#include <thread>

#include "d3d12_features.h"
#include "d3d12_objects.h"
#include "shader_compile_options.h"

namespace caustics::rhi::d3d12 {
namespace {

using DxcoreCreateFactoryProc = HRESULT(STDMETHODCALLTYPE*)(REFIID, void**);

// DXCore enumerates compute-capable adapters (DXCore docs "Enumerating adapters"); it is the adapter API
// available both on Windows and under WSL2, where DXGI does not exist.
std::vector<ComPtr<IDXCoreAdapter>> listAdapters(const RuntimeLibrary& dxcore) {
    std::vector<ComPtr<IDXCoreAdapter>> out;
    auto create = reinterpret_cast<DxcoreCreateFactoryProc>(dxcore.symbol("DXCoreCreateAdapterFactory"));
    if (!create) return out;
    ComPtr<IDXCoreAdapterFactory> factory;
    if (!succeeded(create(__uuidof(IDXCoreAdapterFactory), factory.putVoid()))) return out;
    ComPtr<IDXCoreAdapterList> list;
    const GUID attributes[] = {DXCORE_ADAPTER_ATTRIBUTE_D3D12_GRAPHICS};
    if (!succeeded(factory->CreateAdapterList(1, attributes, __uuidof(IDXCoreAdapterList), list.putVoid()))) return out;
    for (uint32_t i = 0; i < list->GetAdapterCount(); ++i) {
        ComPtr<IDXCoreAdapter> adapter;
        if (succeeded(list->GetAdapter(i, __uuidof(IDXCoreAdapter), adapter.putVoid()))) out.push_back(adapter);
    }
    return out;
}

std::string adapterName(IDXCoreAdapter* adapter) {
    size_t size = 0;
    if (!adapter || !succeeded(adapter->GetPropertySize(DXCoreAdapterProperty::DriverDescription, &size))) return "";
    std::string name(size, '\0');
    adapter->GetProperty(DXCoreAdapterProperty::DriverDescription, size, name.data());
    while (!name.empty() && name.back() == '\0') name.pop_back();
    return name;
}

}  // namespace

Result<DeviceHandle> Device::create(const DeviceDesc& desc, RuntimeLibraries libs) {
    auto device = std::shared_ptr<Device>(new Device());
    device->libs_ = std::move(libs);
    CAUSTICS_CHECK(device->init(desc));
    return DeviceHandle(device);
}

Device::~Device() {
    if (queue_) (void)waitIdle();
    if (releases_) releases_->shutdown();   // idle: objects outliving the device release at once
}

Status Device::init(const DeviceDesc& desc) {
    auto createDevice = reinterpret_cast<PFN_D3D12_CREATE_DEVICE>(libs_.d3d12.symbol("D3D12CreateDevice"));
    auto getDebug = reinterpret_cast<PFN_D3D12_GET_DEBUG_INTERFACE>(libs_.d3d12.symbol("D3D12GetDebugInterface"));
    serializeRootSignature_ = reinterpret_cast<PFN_D3D12_SERIALIZE_VERSIONED_ROOT_SIGNATURE>(
        libs_.d3d12.symbol("D3D12SerializeVersionedRootSignature"));
    if (!createDevice || !serializeRootSignature_)
        return makeError("d3d12 backend: " + libs_.d3d12.path() + " lacks D3D12CreateDevice / "
                         "D3D12SerializeVersionedRootSignature (runtime too old)");
    if (desc.enableValidation) {
        ComPtr<ID3D12Debug> debug;
        if (getDebug && succeeded(getDebug(__uuidof(ID3D12Debug), debug.putVoid()))) {
            debug->EnableDebugLayer();
            debugLayer_ = true;
        } else {
            log(LogLevel::Warning, "d3d12: debug layer requested but not available (install the Graphics Tools "
                                   "optional feature on Windows)");
        }
    }

    std::vector<ComPtr<IDXCoreAdapter>> adapters;
    if (libs_.dxcore.path().size()) adapters = listAdapters(libs_.dxcore);
    if (desc.adapterIndex && *desc.adapterIndex >= adapters.size())
        return makeError("d3d12 backend: adapter index " + std::to_string(*desc.adapterIndex) + " requested, " +
                         std::to_string(adapters.size()) + " D3D12 adapters found");
    std::string refusals;
    auto tryAdapter = [&](IUnknown* adapter, const std::string& name) -> bool {
        ComPtr<ID3D12Device5> dev;
        if (!succeeded(createDevice(adapter, D3D_FEATURE_LEVEL_12_0, __uuidof(ID3D12Device5), dev.putVoid()))) {
            refusals += "\n  " + name + ": no feature level 12_0 / ID3D12Device5";
            return false;
        }
        D3D12_FEATURE_DATA_D3D12_OPTIONS5 o5{};
        dev->CheckFeatureSupport(D3D12_FEATURE_D3D12_OPTIONS5, &o5, sizeof(o5));
        const bool dxr = o5.RaytracingTier >= D3D12_RAYTRACING_TIER_1_0;
        if (desc.requireRayTracing && !dxr) {
            refusals += "\n  " + name + ": no DXR (D3D12_RAYTRACING_TIER_1_0)";
            return false;
        }
        device_ = dev;
        caps_.adapterName = name;
        caps_.rayTracingPipeline = caps_.accelerationStructure = dxr;
        caps_.rayQuery = o5.RaytracingTier >= D3D12_RAYTRACING_TIER_1_1;
        caps_.rayTracingIndirect = o5.RaytracingTier >= D3D12_RAYTRACING_TIER_1_1;   // ExecuteIndirect DispatchRays
        return true;
    };
    bool found = false;
    if (adapters.empty()) {
        found = tryAdapter(nullptr, "default adapter");
    } else if (desc.adapterIndex) {
        found = tryAdapter(adapters[*desc.adapterIndex].get(), adapterName(adapters[*desc.adapterIndex].get()));
    } else {
        for (auto& a : adapters)
            if ((found = tryAdapter(a.get(), adapterName(a.get())))) break;
    }
    if (!found) return makeError("d3d12 backend: no suitable adapter:" + refusals);

    D3D12_COMMAND_QUEUE_DESC q{};
    q.Type = D3D12_COMMAND_LIST_TYPE_DIRECT;
    if (!succeeded(device_->CreateCommandQueue(&q, __uuidof(ID3D12CommandQueue), queue_.putVoid())))
        return makeError("d3d12: CreateCommandQueue failed");
    return finishInit();
}

// What our own and a host's device (d3d12_device_wrap.cpp) share once device_ and queue_ exist.
Status Device::finishInit() {
    caps_.driverName = "D3D12";
    // HLSL has no float atomic add at any shader model (SM 6.6 adds 64-bit integer atomics and only
    // bitwise float compare-exchange), so passes take fixed point or a CAS loop (radiance_atomics.hlsli).
    caps_.shaderFloatAtomicAdd = false;
    const D3D12FeatureReport features = queryD3D12Features(device_.get());
    shaderModel_ = features.highestShaderModel;
    caps_.shaderBufferInt64Atomics = wideFixedPointAtomics(features) && !narrowFixedPointForced();
    caps_.shaderGroupHandleSize = D3D12_SHADER_IDENTIFIER_SIZE_IN_BYTES;
    caps_.shaderGroupHandleAlignment = D3D12_RAYTRACING_SHADER_RECORD_BYTE_ALIGNMENT;
    caps_.shaderGroupBaseAlignment = D3D12_RAYTRACING_SHADER_TABLE_BYTE_ALIGNMENT;
    caps_.maxShaderGroupStride = D3D12_RAYTRACING_MAX_SHADER_RECORD_STRIDE;
    caps_.maxRayRecursionDepth = D3D12_RAYTRACING_MAX_DECLARABLE_TRACE_RECURSION_DEPTH;
    caps_.maxInstanceCount = D3D12_RAYTRACING_MAX_INSTANCES_PER_TOP_LEVEL_ACCELERATION_STRUCTURE;
    caps_.maxPrimitiveCount = D3D12_RAYTRACING_MAX_PRIMITIVES_PER_BOTTOM_LEVEL_ACCELERATION_STRUCTURE;
    caps_.minAccelStructScratchAlignment = D3D12_RAYTRACING_ACCELERATION_STRUCTURE_BYTE_ALIGNMENT;
    caps_.maxTextureDimension2D = D3D12_REQ_TEXTURE2D_U_OR_V_DIMENSION;

    uint64_t frequency = 0;
    if (succeeded(queue_->GetTimestampFrequency(&frequency)) && frequency) caps_.timestampPeriodNs = 1e9 / double(frequency);
    if (!succeeded(device_->CreateFence(0, D3D12_FENCE_FLAG_NONE, __uuidof(ID3D12Fence), fence_.putVoid())))
        return makeError("d3d12: CreateFence failed");
    releases_ = std::make_shared<DeferredReleaseQueue>([fence = fence_.get()] { return fence->GetCompletedValue(); });
    CAUSTICS_TRY(cpuResources_, CpuDescriptorHeap::create(device_.get(), D3D12_DESCRIPTOR_HEAP_TYPE_CBV_SRV_UAV, 65536));
    CAUSTICS_TRY(cpuSamplers_, CpuDescriptorHeap::create(device_.get(), D3D12_DESCRIPTOR_HEAP_TYPE_SAMPLER, 2048));
    CAUSTICS_TRY(compiler_, ShaderCompiler::create(libs_.dxcompiler));
    return okStatus();
}

Result<ComPtr<ID3D12RootSignature>> Device::createRootSignature(const RootSignatureLayout& layout,
                                                                const std::string& name) {
    RootSignatureDescStorage storage(layout);
    ComPtr<ID3DBlob> blob, errors;
    if (!succeeded(serializeRootSignature_(&storage.desc(), blob.put(), errors.put()))) {
        std::string text = errors ? std::string(static_cast<const char*>(errors->GetBufferPointer()),
                                                errors->GetBufferSize())
                                  : "";
        return makeError("d3d12: root signature of '" + name + "' does not serialize: " + text);
    }
    ComPtr<ID3D12RootSignature> rs;
    if (!succeeded(device_->CreateRootSignature(0, blob->GetBufferPointer(), blob->GetBufferSize(),
                                                __uuidof(ID3D12RootSignature), rs.putVoid())))
        return makeError("d3d12: CreateRootSignature failed for '" + name + "'");
    return rs;
}

Result<std::vector<uint8_t>> Device::bytecodeFor(const ShaderCode& code, const std::string& entryPoint,
                                                 ShaderStage stage, bool library) {
    CAUSTICS_CHECK(checkShaderCodeKind(code));
    if (code.kind == ShaderCodeKind::DXIL) return code.bytes;
    CAUSTICS_TRY(std::string profile, hlslTargetProfile(stage, library, shaderModel_));
    std::string source(code.bytes.begin(), code.bytes.end());
    return compiler_->compile(source, code.debugName, dxcArguments(profile, entryPoint, library, debugLayer_));
}

Status Device::waitForFence(uint64_t value) {
    // Polling with a short sleep keeps this portable (no Win32 event object under WSL's adapter).
    while (fence_->GetCompletedValue() < value) {
        if (!succeeded(device_->GetDeviceRemovedReason()))
            return makeError("d3d12: device removed while waiting for fence " + std::to_string(value));
        std::this_thread::sleep_for(std::chrono::microseconds(50));
    }
    releases_->collect();
    return okStatus();
}

Status Device::waitIdle() {
    uint64_t value;
    {
        std::lock_guard lock(submitMutex_);
        value = nextFenceValue_++;
        queue_->Signal(fence_.get(), value);
        releases_->submitted(value);
    }
    return waitForFence(value);
}

Status Device::readBuffer(const BufferHandle& buffer, void* dst, uint64_t bytes, uint64_t offset) {
    auto* b = static_cast<Buffer*>(buffer.get());
    if (!b || !b->mapped) return makeError("d3d12 readBuffer: buffer '" + (b ? b->desc_.debugName : "") + "' is not host-visible");
    if (offset + bytes > b->desc_.byteSize) return makeError("d3d12 readBuffer: range past the end of '" + b->desc_.debugName + "'");
    std::memcpy(dst, static_cast<const uint8_t*>(b->mapped) + offset, bytes);
    return okStatus();
}

Status Device::runImmediate(const std::function<void(ID3D12GraphicsCommandList4*)>& record) {
    ComPtr<ID3D12CommandAllocator> allocator;
    ComPtr<ID3D12GraphicsCommandList4> list;
    if (!succeeded(device_->CreateCommandAllocator(D3D12_COMMAND_LIST_TYPE_DIRECT, __uuidof(ID3D12CommandAllocator),
                                                   allocator.putVoid())) ||
        !succeeded(device_->CreateCommandList(0, D3D12_COMMAND_LIST_TYPE_DIRECT, allocator.get(), nullptr,
                                              __uuidof(ID3D12GraphicsCommandList4), list.putVoid())))
        return makeError("d3d12: could not create an immediate command list");
    record(list.get());
    list->Close();
    ID3D12CommandList* lists[] = {list.get()};
    queue_->ExecuteCommandLists(1, lists);
    return waitIdle();
}

Result<TimestampPoolHandle> Device::createTimestampPool(uint32_t count) {
    auto pool = std::make_shared<TimestampPool>();
    pool->releases = releases_;
    D3D12_QUERY_HEAP_DESC q{D3D12_QUERY_HEAP_TYPE_TIMESTAMP, count, 0};
    if (!succeeded(device_->CreateQueryHeap(&q, __uuidof(ID3D12QueryHeap), pool->heap.putVoid())))
        return makeError("d3d12: CreateQueryHeap failed");
    CAUSTICS_TRY(pool->readback, createCommittedBuffer(device_.get(), uint64_t(count) * 8, D3D12_HEAP_TYPE_READBACK,
                                                       D3D12_RESOURCE_FLAG_NONE, D3D12_RESOURCE_STATE_COPY_DEST,
                                                       "timestamps"));
    pool->readback->Map(0, nullptr, &pool->mapped);
    pool->count = count;
    pool->written.assign(count, 0);
    return TimestampPoolHandle(pool);
}

std::vector<std::optional<double>> Device::readTimestamps(const TimestampPoolHandle& handle, uint32_t first,
                                                          uint32_t count) {
    auto* pool = static_cast<TimestampPool*>(handle.get());
    std::vector<std::optional<double>> out(count);
    // Results are resolved into the readback buffer by the command list; they are valid once its
    // submission completed, which the caller ensures (same contract as the Vulkan backend).
    for (uint32_t i = 0; i < count && first + i < pool->count; ++i) {
        if (!pool->written[first + i]) continue;
        uint64_t ticks;
        std::memcpy(&ticks, static_cast<const uint8_t*>(pool->mapped) + uint64_t(first + i) * 8, 8);
        out[i] = double(ticks) * caps_.timestampPeriodNs;
    }
    return out;
}

}  // namespace caustics::rhi::d3d12
