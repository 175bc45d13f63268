#include "caustics/rhi/native_object.h"

namespace caustics::rhi {

const char* nativeObjectTypeName(NativeObjectType type) {
    switch (type) {
        case NativeObjectType::VkInstance: return "VkInstance";
        case NativeObjectType::VkPhysicalDevice: return "VkPhysicalDevice";
        case NativeObjectType::VkDevice: return "VkDevice";
        case NativeObjectType::VkQueue: return "VkQueue";
        case NativeObjectType::VkImage: return "VkImage";
        case NativeObjectType::VkBuffer: return "VkBuffer";
        case NativeObjectType::VkAccelerationStructureKHR: return "VkAccelerationStructureKHR";
        case NativeObjectType::VkCommandBuffer: return "VkCommandBuffer";
        case NativeObjectType::D3D12Device: return "ID3D12Device5";
        case NativeObjectType::D3D12CommandQueue: return "ID3D12CommandQueue";
        case NativeObjectType::D3D12Resource: return "ID3D12Resource";
        case NativeObjectType::D3D12GraphicsCommandList: return "ID3D12GraphicsCommandList4";
    }
    return "NativeObjectType(?)";
}

}  // namespace caustics::rhi
