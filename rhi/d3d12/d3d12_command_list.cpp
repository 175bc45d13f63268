// Command lists (class in d3d12_command_list.h): creation and queue submission.
#include "d3d12_command_list.h"

namespace caustics::rhi::d3d12 {

Result<CommandListHandle> Device::createCommandList() {
    auto cl = std::make_shared<CommandList>();
    cl->device = this;
    if (!succeeded(device_->CreateCommandAllocator(D3D12_COMMAND_LIST_TYPE_DIRECT, __uuidof(ID3D12CommandAllocator),
                                                   cl->allocator.putVoid())) ||
        !succeeded(device_->CreateCommandList(0, D3D12_COMMAND_LIST_TYPE_DIRECT, cl->allocator.get(), nullptr,
                                              __uuidof(ID3D12GraphicsCommandList4), cl->list.putVoid())))
        return makeError("d3d12: could not create a command list (ID3D12GraphicsCommandList4 needs DXR-era drivers)");
    cl->list->Close();
    CAUSTICS_TRY(cl->resourceRing, GpuDescriptorRing::create(device_.get(), D3D12_DESCRIPTOR_HEAP_TYPE_CBV_SRV_UAV, kRingResources));
    CAUSTICS_TRY(cl->samplerRing, GpuDescriptorRing::create(device_.get(), D3D12_DESCRIPTOR_HEAP_TYPE_SAMPLER, kRingSamplers));
    CAUSTICS_TRY(cl->rtvHeap, CpuDescriptorHeap::create(device_.get(), D3D12_DESCRIPTOR_HEAP_TYPE_RTV, kRecordingRtvs));
    CAUSTICS_TRY(cl->dsvHeap, CpuDescriptorHeap::create(device_.get(), D3D12_DESCRIPTOR_HEAP_TYPE_DSV, kRecordingDsvs));
    CAUSTICS_TRY(cl->uavCpuHeap,
                 CpuDescriptorHeap::create(device_.get(), D3D12_DESCRIPTOR_HEAP_TYPE_CBV_SRV_UAV, kRecordingCpuUavs));
    CAUSTICS_TRY(cl->rtvRange, cl->rtvHeap->allocate(kRecordingRtvs));
    CAUSTICS_TRY(cl->dsvRange, cl->dsvHeap->allocate(kRecordingDsvs));
    CAUSTICS_TRY(cl->uavCpuRange, cl->uavCpuHeap->allocate(kRecordingCpuUavs));
    return CommandListHandle(cl);
}

Result<uint64_t> Device::submit(std::span<const CommandListHandle> lists) {
    std::vector<ID3D12CommandList*> raw;
    for (const CommandListHandle& h : lists) {
        auto* cl = static_cast<CommandList*>(h.get());
        if (!cl->firstError.ok()) return cl->firstError.error();
        raw.push_back(cl->list.get());
    }
    std::lock_guard lock(submitMutex_);
    if (!raw.empty()) queue_->ExecuteCommandLists(UINT(raw.size()), raw.data());
    const uint64_t value = nextFenceValue_++;
    if (!succeeded(queue_->Signal(fence_.get(), value))) return makeError("d3d12: queue Signal failed");
    return value;
}

}  // namespace caustics::rhi::d3d12
