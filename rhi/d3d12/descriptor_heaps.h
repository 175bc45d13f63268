#pragma once
// Descriptor heaps. Binding sets write their descriptors once into a CPU-only staging heap; at
// setBindingSet the command list copies the set's range into a shader-visible ring (one per command
// list, reset at begin) and points the root table at it (the "CPU staging + GPU ring" scheme of
// MiniEngine's DynamicDescriptorHeap, simplified to whole-table copies).
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "d3d12_headers.h"
#include "caustics/rhi/result.h"

namespace caustics::rhi::d3d12 {

struct DescriptorRange {
    D3D12_CPU_DESCRIPTOR_HANDLE cpu{};
    uint32_t first = 0, count = 0;
};

// A non-shader-visible heap handing out ranges with first-fit reuse of freed ranges.
class CpuDescriptorHeap {
public:
    static Result<std::unique_ptr<CpuDescriptorHeap>> create(ID3D12Device* device, D3D12_DESCRIPTOR_HEAP_TYPE type,
                                                             uint32_t capacity);
    Result<DescriptorRange> allocate(uint32_t count);
    void release(const DescriptorRange& range);
    D3D12_CPU_DESCRIPTOR_HANDLE at(uint32_t index) const { return {start_.ptr + size_t(index) * increment_}; }
    uint32_t increment() const { return increment_; }
    D3D12_DESCRIPTOR_HEAP_TYPE type() const { return type_; }

private:
    ComPtr<ID3D12DescriptorHeap> heap_;
    D3D12_DESCRIPTOR_HEAP_TYPE type_{};
    D3D12_CPU_DESCRIPTOR_HANDLE start_{};
    uint32_t increment_ = 0, capacity_ = 0, top_ = 0;
    std::vector<DescriptorRange> free_;
    std::mutex mutex_;
};

// A shader-visible heap used as a linear ring by one command list at a time.
class GpuDescriptorRing {
public:
    static Result<std::unique_ptr<GpuDescriptorRing>> create(ID3D12Device* device, D3D12_DESCRIPTOR_HEAP_TYPE type,
                                                             uint32_t capacity);
    void reset() { top_ = 0; }
    // Copies `count` descriptors starting at `src` and returns the GPU handle of the copy.
    Result<D3D12_GPU_DESCRIPTOR_HANDLE> push(ID3D12Device* device, D3D12_CPU_DESCRIPTOR_HANDLE src, uint32_t count);
    ID3D12DescriptorHeap* heap() const { return heap_.get(); }

private:
    ComPtr<ID3D12DescriptorHeap> heap_;
    D3D12_DESCRIPTOR_HEAP_TYPE type_{};
    D3D12_CPU_DESCRIPTOR_HANDLE cpuStart_{};
    D3D12_GPU_DESCRIPTOR_HANDLE gpuStart_{};
    uint32_t increment_ = 0, capacity_ = 0, top_ = 0;
};

}  // namespace caustics::rhi::d3d12
