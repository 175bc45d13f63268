#pragma once
// Native objects behind RHI objects, for host engines that embed the module (NVRHI's getNativeObject):
// the host asks an object for a native type and gets the handle or a null NativeObject when the object
// has no such thing (wrong backend, wrong kind). Backend-free: no vulkan.h or d3d12.h here; the host
// casts with as<VkImage>() or as<ID3D12Resource*>(). Contract: docs/embedding.md "Device and resources".
#include <cstdint>
#include <type_traits>

namespace caustics::rhi {

enum class NativeObjectType : uint32_t {
    // Vulkan
    VkInstance,
    VkPhysicalDevice,
    VkDevice,
    VkQueue,
    VkImage,
    VkBuffer,
    VkAccelerationStructureKHR,
    VkCommandBuffer,
    // D3D12 (COM pointers; no reference is added)
    D3D12Device,               // ID3D12Device5*
    D3D12CommandQueue,         // ID3D12CommandQueue*
    D3D12Resource,             // ID3D12Resource* of a texture, buffer or acceleration structure's storage
    D3D12GraphicsCommandList,  // ID3D12GraphicsCommandList4*
};

const char* nativeObjectTypeName(NativeObjectType type);

// A Vulkan handle (dispatchable or not) or a D3D12 interface pointer as 64 bits; 0 = none.
struct NativeObject {
    uint64_t handle = 0;

    NativeObject() = default;
    explicit NativeObject(uint64_t value) : handle(value) {}
    template <typename T>
    static NativeObject from(T object) {
        if constexpr (std::is_pointer_v<T>) return NativeObject(uint64_t(reinterpret_cast<uintptr_t>(object)));
        else return NativeObject(uint64_t(object));
    }

    bool valid() const { return handle != 0; }
    explicit operator bool() const { return valid(); }

    // Vulkan's non-dispatchable handles are pointers on 64-bit targets and uint64_t on 32-bit ones.
    template <typename T>
    T as() const {
        if constexpr (std::is_pointer_v<T>) return reinterpret_cast<T>(uintptr_t(handle));
        else return T(handle);
    }
};

}  // namespace caustics::rhi
