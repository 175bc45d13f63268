#pragma once
// One place that pulls in the D3D12 API declarations. Windows: the SDK (or DirectX-Headers when
// CAUSTICS_D3D12_DIRECTX_HEADERS is set); Linux: DirectX-Headers' WSL adapter, which declares the
// COM base types that d3d12.h expects. Nothing here links d3d12: the backend loads it at run time.
#if defined(CAUSTICS_D3D12_DIRECTX_HEADERS)
#if !defined(_WIN32)
#include <wsl/winadapter.h>
#else
// MinGW-w64's rpcndr.h calls itself version 475 and refuses the 500 that MIDL-generated d3d12.h
// requests, although it declares everything d3d12.h uses; included first (through windows.h), it
// is not asked again. MSVC's SDK headers pass either way.
#include <windows.h>
#endif
#include <directx/d3d12.h>
#include <directx/dxcore.h>
#include <dxguids/dxguids.h>
#else
#include <windows.h>
#include <d3d12.h>
#include <dxcore.h>
#endif

#include <utility>

namespace caustics::rhi::d3d12 {

// Minimal owning COM pointer (WRL's ComPtr differs between the SDK and the WSL stubs).
template <typename T>
class ComPtr {
public:
    ComPtr() = default;
    ComPtr(const ComPtr& o) : p_(o.p_) { if (p_) p_->AddRef(); }
    ComPtr(ComPtr&& o) noexcept : p_(std::exchange(o.p_, nullptr)) {}
    ComPtr& operator=(ComPtr o) noexcept { std::swap(p_, o.p_); return *this; }
    ~ComPtr() { reset(); }

    void reset() { if (p_) std::exchange(p_, nullptr)->Release(); }
    T* get() const { return p_; }
    T* operator->() const { return p_; }
    explicit operator bool() const { return p_ != nullptr; }
    // For out-parameters: releases what was held.
    T** put() { reset(); return &p_; }
    void** putVoid() { return reinterpret_cast<void**>(put()); }

private:
    T* p_ = nullptr;
};

inline bool succeeded(HRESULT hr) { return hr >= 0; }

// D3D12 methods that return a struct. MSVC's C++ ABI returns it through a hidden pointer even when it
// is small; GCC and Clang targeting Windows (MinGW) would not, so DirectX-Headers declares these with an
// explicit `RetVal` out-parameter there (d3d12.h: `#if defined(_MSC_VER) || !defined(_WIN32)`). Call
// them through these, never directly, so the backend builds with MSVC, MinGW and the WSL headers.
#if defined(_MSC_VER) || !defined(_WIN32)
inline constexpr bool kStructReturnsByValue = true;
#else
inline constexpr bool kStructReturnsByValue = false;
#endif
// `method` is called as object->method(args...) where the declaration returns the struct, else as
// object->method(&out, args...).
template <typename Out, typename Object, typename Method, typename... Args>
Out structReturn(Object* object, Method method, Args... args) {
    if constexpr (kStructReturnsByValue) {
        return (object->*method)(args...);
    } else {
        Out out{};
        (object->*method)(&out, args...);
        return out;
    }
}
inline D3D12_RESOURCE_ALLOCATION_INFO resourceAllocationInfo(ID3D12Device* device, UINT visibleMask, UINT count,
                                                             const D3D12_RESOURCE_DESC* descs) {
    return structReturn<D3D12_RESOURCE_ALLOCATION_INFO>(device, &ID3D12Device::GetResourceAllocationInfo, visibleMask,
                                                        count, descs);
}
inline D3D12_CPU_DESCRIPTOR_HANDLE cpuDescriptorStart(ID3D12DescriptorHeap* heap) {
    return structReturn<D3D12_CPU_DESCRIPTOR_HANDLE>(heap, &ID3D12DescriptorHeap::GetCPUDescriptorHandleForHeapStart);
}
inline D3D12_GPU_DESCRIPTOR_HANDLE gpuDescriptorStart(ID3D12DescriptorHeap* heap) {
    return structReturn<D3D12_GPU_DESCRIPTOR_HANDLE>(heap, &ID3D12DescriptorHeap::GetGPUDescriptorHandleForHeapStart);
}
inline D3D12_RESOURCE_DESC resourceDesc(ID3D12Resource* resource) {
    return structReturn<D3D12_RESOURCE_DESC>(resource, &ID3D12Resource::GetDesc);
}

}  // namespace caustics::rhi::d3d12
