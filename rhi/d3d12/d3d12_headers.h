#pragma once
// One place that pulls in the D3D12 API declarations. Windows: the SDK (or DirectX-Headers when
// CAUSTICS_D3D12_DIRECTX_HEADERS is set); Linux: DirectX-Headers' WSL adapter, which declares the
// COM base types that d3d12.h expects. Nothing here links d3d12: the backend loads it at run time.
#if defined(CAUSTICS_D3D12_DIRECTX_HEADERS)
#if !defined(_WIN32)
#include <wsl/winadapter.h>
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

}  // namespace caustics::rhi::d3d12
