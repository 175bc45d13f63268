// wrapD3D12Device: the backend's Device over a host engine's ID3D12Device5 and direct queue
// (d3d12_interop.h). References are held on both (COM), never released early and never more than
// taken; the module creates only its fence, descriptor heaps and its own resources.
#include "caustics/rhi/d3d12_interop.h"
#include "d3d12_device.h"
#include "d3d12_features.h"
#include "host_objects.h"

namespace caustics::rhi {
namespace d3d12 {
Result<DeviceHandle> Device::wrap(ID3D12Device5* device, ID3D12CommandQueue* queue, const std::string& name,
                                  RuntimeLibraries libs) {
    auto wrapped = std::shared_ptr<Device>(new Device());
    wrapped->libs_ = std::move(libs);
    wrapped->serializeRootSignature_ = reinterpret_cast<PFN_D3D12_SERIALIZE_VERSIONED_ROOT_SIGNATURE>(
        wrapped->libs_.d3d12.symbol("D3D12SerializeVersionedRootSignature"));
    if (!wrapped->serializeRootSignature_)
        return makeError("d3d12: " + wrapped->libs_.d3d12.path() + " lacks D3D12SerializeVersionedRootSignature");
    wrapped->device_ = holdReference(device);
    wrapped->queue_ = holdReference(queue);
    D3D12_FEATURE_DATA_D3D12_OPTIONS5 o5{};
    device->CheckFeatureSupport(D3D12_FEATURE_D3D12_OPTIONS5, &o5, sizeof(o5));
    wrapped->caps_.adapterName = name;
    wrapped->caps_.rayTracingPipeline = wrapped->caps_.accelerationStructure = o5.RaytracingTier >= D3D12_RAYTRACING_TIER_1_0;
    wrapped->caps_.rayQuery = o5.RaytracingTier >= D3D12_RAYTRACING_TIER_1_1;
    CAUSTICS_CHECK(wrapped->finishInit());
    return DeviceHandle(wrapped);
}

std::pair<ID3D12Fence*, uint64_t> Device::reserveHostSignal() {
    std::lock_guard lock(submitMutex_);
    return {fence_.get(), nextFenceValue_++};
}

NativeObject Device::getNativeObject(NativeObjectType type) const {
    if (type == NativeObjectType::D3D12Device) return NativeObject::from(device_.get());
    if (type == NativeObjectType::D3D12CommandQueue) return NativeObject::from(queue_.get());
    return {};
}

}  // namespace d3d12

Result<DeviceHandle> wrapD3D12Device(const D3D12DeviceImport& desc) {
    if (!desc.device || !desc.queue)
        return makeError("d3d12: wrapD3D12Device '" + desc.debugName + "': D3D12DeviceImport lacks " +
                         (desc.device ? "queue" : desc.queue ? "device" : "device, queue"));
    const auto queueDesc = d3d12::describe<D3D12_COMMAND_QUEUE_DESC>(desc.queue);
    if (queueDesc.Type != D3D12_COMMAND_LIST_TYPE_DIRECT)
        return makeError("d3d12: wrapD3D12Device '" + desc.debugName + "': the queue is not a DIRECT queue");
    const D3D12FeatureReport report = d3d12::queryD3D12Features(desc.device);
    CAUSTICS_CHECK(checkD3D12DeviceRequirements(report, desc.requireRayTracing, desc.debugName));
    CAUSTICS_TRY(d3d12::RuntimeLibraries libs, d3d12::loadRuntimeLibraries());
    return d3d12::Device::wrap(desc.device, desc.queue, desc.debugName, std::move(libs));
}

}  // namespace caustics::rhi
