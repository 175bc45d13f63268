// The backend's entry point for rhi::createDevice.
#include "../factory/backend_entry_points.h"
#include "vk_device.h"

namespace caustics::rhi::vulkan {

Result<DeviceHandle> createDevice(const DeviceDesc& desc) {
    auto device = VulkanDevice::create(desc);
    if (!device) return device.error();
    return DeviceHandle(device.value());
}

}  // namespace caustics::rhi::vulkan
