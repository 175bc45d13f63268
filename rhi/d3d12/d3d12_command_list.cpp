// Command lists (class in d3d12_command_list.h): creation and queue submission.
#include "d3d12_command_list.h"

namespace caustics::rhi::d3d12 {

Result<CommandListHandle> Device::createCommandList() {
    auto cl = std::make_shared<CommandList>();
    cl->device = this;
    cl->releases = releases_;
    if (!succeeded(device_->CreateCommandAllocator(D3D12_COMMAND_LIST_TYPE_DIRECT, __uuidof(ID3D12CommandAllocator),
                                                   cl->allocator.putVoid())) ||
        !succeeded(device_->CreateCommandList(0, D3D12_COMMAND_LIST_TYPE_DIRECT, cl->allocator.get(), nullptr,
                                              __uuidof(ID3D12GraphicsCommandList4), cl->list.putVoid())))
        return makeError("d3d12: could not create a command list (ID3D12GraphicsCommandList4 needs DXR-era drivers)");
    cl->list->Close();
    CAUSTICS_CHECK(cl->createDescriptorStorage(device_.get()));
    return CommandListHandle(cl);
}

Status CommandList::createDescriptorStorage(ID3D12Device* d3d) {
    CAUSTICS_TRY(resourceRing, GpuDescriptorRing::create(d3d, D3D12_DESCRIPTOR_HEAP_TYPE_CBV_SRV_UAV, kRingResources));
    CAUSTICS_TRY(samplerRing, GpuDescriptorRing::create(d3d, D3D12_DESCRIPTOR_HEAP_TYPE_SAMPLER, kRingSamplers));
    CAUSTICS_TRY(rtvHeap, CpuDescriptorHeap::create(d3d, D3D12_DESCRIPTOR_HEAP_TYPE_RTV, kRecordingRtvs));
    CAUSTICS_TRY(dsvHeap, CpuDescriptorHeap::create(d3d, D3D12_DESCRIPTOR_HEAP_TYPE_DSV, kRecordingDsvs));
    CAUSTICS_TRY(uavCpuHeap, CpuDescriptorHeap::create(d3d, D3D12_DESCRIPTOR_HEAP_TYPE_CBV_SRV_UAV, kRecordingCpuUavs));
    CAUSTICS_TRY(rtvRange, rtvHeap->allocate(kRecordingRtvs));
    CAUSTICS_TRY(dsvRange, dsvHeap->allocate(kRecordingDsvs));
    CAUSTICS_TRY(uavCpuRange, uavCpuHeap->allocate(kRecordingCpuUavs));
    return okStatus();
}

Result<uint64_t> Device::submit(std::span<const CommandListHandle> lists) {
    std::vector<ID3D12CommandList*> raw;
    for (const CommandListHandle& h : lists) {
        auto* cl = static_cast<CommandList*>(h.get());
        if (!cl->allocator) return makeError("d3d12: submit of a wrapped host command list; the host executes it itself");
        if (!cl->firstError.ok()) return cl->firstError.error();
        raw.push_back(cl->list.get());
    }
    std::lock_guard lock(submitMutex_);
    if (!raw.empty()) queue_->ExecuteCommandLists(UINT(raw.size()), raw.data());
    const uint64_t value = nextFenceValue_++;
    if (!succeeded(queue_->Signal(fence_.get(), value))) return makeError("d3d12: queue Signal failed");
    releases_->submitted(value);
    releases_->collect();
    return value;
}

}  // namespace caustics::rhi::d3d12
