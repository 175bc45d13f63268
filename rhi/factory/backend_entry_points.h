#pragma once
// Entry points each backend library provides; only the factory sees them.
#include "caustics/rhi/device.h"

namespace caustics::rhi::vulkan {
Result<DeviceHandle> createDevice(const DeviceDesc& desc);
}
namespace caustics::rhi::d3d12 {
Result<DeviceHandle> createDevice(const DeviceDesc& desc);
}
