// wrapVulkanDevice: an IDevice over a host engine's VkDevice (vulkan_interop.h). Nothing of the host's
// is created or destroyed; the context only records the handles (ownsDevice = false) and adds the
// backend's own timeline semaphore, memory blocks and descriptor pools.
#include <algorithm>
#include <string>

#include "caustics/rhi/vulkan_interop.h"
#include "vk_binding.h"
#include "vk_device.h"
#include "vk_device_setup.h"
#include "vk_memory.h"

namespace caustics::rhi {
namespace {

Status checkHandles(const VulkanDeviceImport& d) {
    std::string missing;
    auto need = [&](bool present, const char* field) {
        if (!present) missing += (missing.empty() ? "" : ", ") + std::string(field);
    };
    need(d.instance != VK_NULL_HANDLE, "instance");
    need(d.physicalDevice != VK_NULL_HANDLE, "physicalDevice");
    need(d.device != VK_NULL_HANDLE, "device");
    need(d.queue != VK_NULL_HANDLE, "queue");
    need(d.getInstanceProcAddr != nullptr, "getInstanceProcAddr");
    need(d.enabledFeatures != nullptr, "enabledFeatures");
    if (missing.empty()) return okStatus();
    return makeError("vulkan: wrapVulkanDevice '" + d.debugName + "': VulkanDeviceImport lacks " + missing);
}

}  // namespace

Result<DeviceHandle> wrapVulkanDevice(const VulkanDeviceImport& desc) {
    CAUSTICS_CHECK(checkHandles(desc));
    auto has = [&](const std::vector<std::string>& list, const char* name) {
        return std::find(list.begin(), list.end(), name) != list.end();
    };
    // Every call from here on goes through the host's vkGetInstanceProcAddr (vk_dispatch.h).
    auto context = std::make_shared<vulkan::VulkanContext>();
    context->ownsDevice = false;
    const std::string who = "wrapVulkanDevice '" + desc.debugName + "'";
    CAUSTICS_CHECK(vulkan::loadInstanceDispatch(context->fn, desc.getInstanceProcAddr, desc.instance,
                                                has(desc.enabledInstanceExtensions, VK_EXT_DEBUG_UTILS_EXTENSION_NAME),
                                                who + " (the host's vkGetInstanceProcAddr)"));
    VkPhysicalDeviceProperties props;
    context->fn.vkGetPhysicalDeviceProperties(desc.physicalDevice, &props);
    const VulkanEnabledFeatures features = readVulkanFeatureChain(desc.enabledFeatures);
    CAUSTICS_CHECK(checkVulkanDeviceRequirements(desc.apiVersion, desc.enabledExtensions, features,
                                                 desc.requireRayTracing,
                                                 desc.debugName + " on " + props.deviceName));

    context->instance = desc.instance;
    context->physicalDevice = desc.physicalDevice;
    context->device = desc.device;
    context->queue = desc.queue;
    context->queueFamily = desc.queueFamily;

    const auto& ext = desc.enabledExtensions;
    vulkan::EnabledDeviceParts parts;
    parts.accelStruct = has(ext, VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME) && features.accelerationStructure;
    parts.rayTracingPipeline =
        parts.accelStruct && has(ext, VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME) && features.rayTracingPipeline;
    parts.rayQuery = parts.accelStruct && has(ext, VK_KHR_RAY_QUERY_EXTENSION_NAME) && features.rayQuery;
    parts.traceRaysIndirect = parts.rayTracingPipeline && features.rayTracingPipelineTraceRaysIndirect;
    parts.floatAtomicAdd = has(ext, VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME) &&
                           features.shaderBufferFloat32AtomicAdd && features.shaderImageFloat32AtomicAdd;
    CAUSTICS_CHECK(vulkan::loadDeviceDispatch(context->fn, context->device, parts.accelStruct, parts.rayTracingPipeline,
                                              who + " (the host's vkGetDeviceProcAddr)"));
    CAUSTICS_CHECK(vulkan::finishDeviceSetup(*context, parts));
    context->allocator = std::make_unique<vulkan::MemoryAllocator>(*context);
    context->descriptors = std::make_unique<vulkan::DescriptorAllocator>(*context);
    log(LogLevel::Info, "vulkan: wrapped the host's device '" + context->capabilities.adapterName + "'");
    return DeviceHandle(vulkan::VulkanDevice::adopt(std::move(context)));
}

}  // namespace caustics::rhi
