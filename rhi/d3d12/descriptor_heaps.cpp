#include "descriptor_heaps.h"

#include <memory>
#include <string>

namespace caustics::rhi::d3d12 {

Result<std::unique_ptr<CpuDescriptorHeap>> CpuDescriptorHeap::create(ID3D12Device* device,
                                                                     D3D12_DESCRIPTOR_HEAP_TYPE type,
                                                                     uint32_t capacity) {
    auto h = std::unique_ptr<CpuDescriptorHeap>(new CpuDescriptorHeap());
    D3D12_DESCRIPTOR_HEAP_DESC d{type, capacity, D3D12_DESCRIPTOR_HEAP_FLAG_NONE, 0};
    if (!succeeded(device->CreateDescriptorHeap(&d, __uuidof(ID3D12DescriptorHeap), h->heap_.putVoid())))
        return makeError("d3d12: CreateDescriptorHeap (CPU staging) failed");
    h->type_ = type;
    h->start_ = cpuDescriptorStart(h->heap_.get());
    h->increment_ = device->GetDescriptorHandleIncrementSize(type);
    h->capacity_ = capacity;
    return h;
}

Result<DescriptorRange> CpuDescriptorHeap::allocate(uint32_t count) {
    std::lock_guard lock(mutex_);
    for (size_t i = 0; i < free_.size(); ++i) {
        if (free_[i].count < count) continue;
        DescriptorRange r{at(free_[i].first), free_[i].first, count};
        free_[i].first += count;
        free_[i].count -= count;
        if (free_[i].count == 0) free_.erase(free_.begin() + long(i));
        return r;
    }
    if (top_ + count > capacity_)
        return makeError("d3d12: CPU descriptor heap full (" + std::to_string(capacity_) + " descriptors)");
    DescriptorRange r{at(top_), top_, count};
    top_ += count;
    return r;
}

void CpuDescriptorHeap::release(const DescriptorRange& range) {
    if (range.count == 0) return;
    std::lock_guard lock(mutex_);
    free_.push_back(range);
}

Result<std::unique_ptr<GpuDescriptorRing>> GpuDescriptorRing::create(ID3D12Device* device,
                                                                     D3D12_DESCRIPTOR_HEAP_TYPE type,
                                                                     uint32_t capacity) {
    auto r = std::unique_ptr<GpuDescriptorRing>(new GpuDescriptorRing());
    D3D12_DESCRIPTOR_HEAP_DESC d{type, capacity, D3D12_DESCRIPTOR_HEAP_FLAG_SHADER_VISIBLE, 0};
    if (!succeeded(device->CreateDescriptorHeap(&d, __uuidof(ID3D12DescriptorHeap), r->heap_.putVoid())))
        return makeError("d3d12: CreateDescriptorHeap (shader-visible) failed");
    r->type_ = type;
    r->cpuStart_ = cpuDescriptorStart(r->heap_.get());
    r->gpuStart_ = gpuDescriptorStart(r->heap_.get());
    r->increment_ = device->GetDescriptorHandleIncrementSize(type);
    r->capacity_ = capacity;
    return r;
}

Result<D3D12_GPU_DESCRIPTOR_HANDLE> GpuDescriptorRing::push(ID3D12Device* device, D3D12_CPU_DESCRIPTOR_HANDLE src,
                                                            uint32_t count) {
    if (top_ + count > capacity_)
        return makeError("d3d12: shader-visible descriptor ring full for this command list (" +
                         std::to_string(capacity_) + " descriptors); split the work over more command lists");
    D3D12_CPU_DESCRIPTOR_HANDLE dst{cpuStart_.ptr + size_t(top_) * increment_};
    if (count) device->CopyDescriptorsSimple(count, dst, src, type_);
    D3D12_GPU_DESCRIPTOR_HANDLE gpu{gpuStart_.ptr + uint64_t(top_) * increment_};
    top_ += count;
    return gpu;
}

}  // namespace caustics::rhi::d3d12
