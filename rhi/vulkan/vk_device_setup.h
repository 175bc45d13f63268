#pragma once
// What every Vulkan device needs once a VkDevice exists, whether this backend created it
// (vk_physical_device.cpp) or a host engine did (vk_device_wrap.cpp): properties, capabilities,
// and the timeline semaphore that serves as the device fence.
#include "vk_context.h"

namespace caustics::rhi::vulkan {

// Which optional parts of the device are enabled (extension and feature both on).
struct EnabledDeviceParts {
    bool accelStruct = false;
    bool rayTracingPipeline = false;
    bool rayQuery = false;
    bool floatAtomicAdd = false;   // buffer and image float32 atomicAdd
    bool traceRaysIndirect = false;   // rayTracingPipelineTraceRaysIndirect
    bool int64Atomics = false;     // shaderInt64 + shaderBufferInt64Atomics (Vulkan 1.2 core)
};

// Needs context.physicalDevice, device and queue set and context.fn loaded (vk_dispatch.h): the
// loader's entry points for our own device, the host's (through its vkGetInstanceProcAddr) for a
// wrapped one.
Status finishDeviceSetup(VulkanContext& context, const EnabledDeviceParts& parts);

}  // namespace caustics::rhi::vulkan
