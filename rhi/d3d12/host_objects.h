#pragma once
// Helpers for a host engine's D3D12 objects (d3d12_device_wrap.cpp, d3d12_interop_resources.cpp):
// a reference of our own on the host's object, and descriptors read through the MinGW-safe form of
// GetDesc (DirectX-Headers declare struct-returning COM methods differently for MinGW).
#include "d3d12_headers.h"

namespace caustics::rhi::d3d12 {

// AddRef'd: the ComPtr's release gives back exactly the reference taken here.
template <typename T>
ComPtr<T> holdReference(T* object) {
    ComPtr<T> held;
    object->AddRef();
    *held.put() = object;
    return held;
}

template <typename Desc, typename Object>
Desc describe(Object* object) {
#if defined(_MSC_VER) || !defined(_WIN32)
    return object->GetDesc();
#else
    Desc desc;
    object->GetDesc(&desc);
    return desc;
#endif
}

}  // namespace caustics::rhi::d3d12
