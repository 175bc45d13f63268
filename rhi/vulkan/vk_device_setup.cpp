#include "vk_device_setup.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>

namespace caustics::rhi::vulkan {
namespace {

// CAUSTICS_FORCE_FIXED_POINT=1 reports no float atomics, so the passes take the fixed-point path that
// D3D12 always takes; the caustic GPU tests run once more this way (docs/d3d12.md). =32 also reports
// no 64-bit integer atomics: the narrow (one uint per channel) fixed-point words.
bool forceFixedPointAccumulation() {
    const char* v = std::getenv("CAUSTICS_FORCE_FIXED_POINT");
    return v && *v && std::strcmp(v, "0") != 0;
}
bool forceNarrowFixedPoint() {
    const char* v = std::getenv("CAUSTICS_FORCE_FIXED_POINT");
    return v && std::strcmp(v, "32") == 0;
}

}  // namespace

Status finishDeviceSetup(VulkanContext& context, const EnabledDeviceParts& parts) {
    context.fn.vkGetPhysicalDeviceMemoryProperties(context.physicalDevice, &context.memoryProperties);

    VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceMaintenance3Properties maintenance3{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
    props.pNext = &maintenance3;
    maintenance3.pNext = &driver;
    if (parts.accelStruct) {
        context.accelStructProperties.pNext = driver.pNext;
        driver.pNext = &context.accelStructProperties;
    }
    if (parts.rayTracingPipeline) {
        context.rayTracingProperties.pNext = driver.pNext;
        driver.pNext = &context.rayTracingProperties;
    }
    context.fn.vkGetPhysicalDeviceProperties2(context.physicalDevice, &props);
    context.rayTracingProperties.pNext = nullptr;
    context.accelStructProperties.pNext = nullptr;
    context.properties = props.properties;

    Capabilities& caps = context.capabilities;
    caps.adapterName = props.properties.deviceName;
    caps.driverName = std::string(driver.driverName) + " " + driver.driverInfo;
    caps.accelerationStructure = parts.accelStruct;
    caps.rayTracingPipeline = parts.rayTracingPipeline;
    caps.rayQuery = parts.rayQuery;
    caps.shaderFloatAtomicAdd = parts.floatAtomicAdd && !forceFixedPointAccumulation();
    caps.shaderBufferInt64Atomics = parts.int64Atomics && !forceNarrowFixedPoint();
    caps.rayTracingIndirect = parts.rayTracingPipeline && parts.traceRaysIndirect;
    if (parts.rayTracingPipeline) {
        const auto& rp = context.rayTracingProperties;
        caps.shaderGroupHandleSize = rp.shaderGroupHandleSize;
        caps.shaderGroupHandleAlignment = rp.shaderGroupHandleAlignment;
        caps.shaderGroupBaseAlignment = rp.shaderGroupBaseAlignment;
        caps.maxShaderGroupStride = rp.maxShaderGroupStride;
        caps.maxRayRecursionDepth = rp.maxRayRecursionDepth;
    }
    if (parts.accelStruct) {
        caps.maxInstanceCount = uint32_t(std::min<uint64_t>(context.accelStructProperties.maxInstanceCount, UINT32_MAX));
        caps.maxPrimitiveCount = context.accelStructProperties.maxPrimitiveCount;
        caps.minAccelStructScratchAlignment = context.accelStructProperties.minAccelerationStructureScratchOffsetAlignment;
    }
    caps.timestampPeriodNs = props.properties.limits.timestampPeriod;
    caps.maxTextureDimension2D = props.properties.limits.maxImageDimension2D;
    caps.maxAllocationBytes = maintenance3.maxMemoryAllocationSize;
    for (uint32_t h = 0; h < context.memoryProperties.memoryHeapCount; ++h)
        if (context.memoryProperties.memoryHeaps[h].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
            caps.deviceMemoryBytes = std::max<uint64_t>(caps.deviceMemoryBytes, context.memoryProperties.memoryHeaps[h].size);


    VkSemaphoreTypeCreateInfo type{VK_STRUCTURE_TYPE_SEMAPHORE_TYPE_CREATE_INFO};
    type.semaphoreType = VK_SEMAPHORE_TYPE_TIMELINE;
    type.initialValue = 0;
    VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    semaphore.pNext = &type;
    VkResult r = context.fn.vkCreateSemaphore(context.device, &semaphore, nullptr, &context.timeline);
    if (r != VK_SUCCESS) return vkError(r, "vkCreateSemaphore (timeline)");
    context.setName(VK_OBJECT_TYPE_SEMAPHORE, context.timeline, "device fence");
    return okStatus();
}

}  // namespace caustics::rhi::vulkan
