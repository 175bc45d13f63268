// Device-free checks of a host engine's Vulkan device (vulkan_interop.h): which features its
// VkDeviceCreateInfo::pNext chain enables, and whether the API version, extensions and features
// cover what this backend calls and what the module's shaders declare. One error names every gap.
#include <algorithm>
#include <string>
#include <vector>

#include "caustics/rhi/vulkan_interop.h"

namespace caustics::rhi {
namespace {

// Every Vulkan structure starts with sType and pNext (spec 3.3 "Valid Usage for Structure Pointer Chains").
struct ChainLink {
    VkStructureType sType;
    const ChainLink* pNext;
};

template <typename T>
const T& as(const ChainLink* link) {
    return *reinterpret_cast<const T*>(link);
}

}  // namespace

VulkanEnabledFeatures readVulkanFeatureChain(const void* chain) {
    VulkanEnabledFeatures f;
    auto on = [](bool& flag, VkBool32 value) { flag = flag || value == VK_TRUE; };
    for (auto* link = static_cast<const ChainLink*>(chain); link; link = link->pNext) {
        switch (link->sType) {
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES: {
                const auto& v = as<VkPhysicalDeviceVulkan12Features>(link);
                on(f.bufferDeviceAddress, v.bufferDeviceAddress);
                on(f.runtimeDescriptorArray, v.runtimeDescriptorArray);
                on(f.shaderSampledImageArrayNonUniformIndexing, v.shaderSampledImageArrayNonUniformIndexing);
                on(f.descriptorBindingPartiallyBound, v.descriptorBindingPartiallyBound);
                on(f.timelineSemaphore, v.timelineSemaphore);
                on(f.hostQueryReset, v.hostQueryReset);
                break;
            }
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES: {
                const auto& v = as<VkPhysicalDeviceVulkan13Features>(link);
                on(f.dynamicRendering, v.dynamicRendering);
                on(f.synchronization2, v.synchronization2);
                break;
            }
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_BUFFER_DEVICE_ADDRESS_FEATURES:
                on(f.bufferDeviceAddress, as<VkPhysicalDeviceBufferDeviceAddressFeatures>(link).bufferDeviceAddress);
                break;
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DESCRIPTOR_INDEXING_FEATURES: {
                const auto& v = as<VkPhysicalDeviceDescriptorIndexingFeatures>(link);
                on(f.runtimeDescriptorArray, v.runtimeDescriptorArray);
                on(f.shaderSampledImageArrayNonUniformIndexing, v.shaderSampledImageArrayNonUniformIndexing);
                on(f.descriptorBindingPartiallyBound, v.descriptorBindingPartiallyBound);
                break;
            }
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TIMELINE_SEMAPHORE_FEATURES:
                on(f.timelineSemaphore, as<VkPhysicalDeviceTimelineSemaphoreFeatures>(link).timelineSemaphore);
                break;
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_HOST_QUERY_RESET_FEATURES:
                on(f.hostQueryReset, as<VkPhysicalDeviceHostQueryResetFeatures>(link).hostQueryReset);
                break;
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DYNAMIC_RENDERING_FEATURES:
                on(f.dynamicRendering, as<VkPhysicalDeviceDynamicRenderingFeatures>(link).dynamicRendering);
                break;
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SYNCHRONIZATION_2_FEATURES:
                on(f.synchronization2, as<VkPhysicalDeviceSynchronization2Features>(link).synchronization2);
                break;
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR:
                on(f.accelerationStructure,
                   as<VkPhysicalDeviceAccelerationStructureFeaturesKHR>(link).accelerationStructure);
                break;
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR:
                on(f.rayTracingPipeline, as<VkPhysicalDeviceRayTracingPipelineFeaturesKHR>(link).rayTracingPipeline);
                on(f.rayTracingPipelineTraceRaysIndirect,
                   as<VkPhysicalDeviceRayTracingPipelineFeaturesKHR>(link).rayTracingPipelineTraceRaysIndirect);
                break;
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR:
                on(f.rayQuery, as<VkPhysicalDeviceRayQueryFeaturesKHR>(link).rayQuery);
                break;
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_ATOMIC_FLOAT_FEATURES_EXT: {
                const auto& v = as<VkPhysicalDeviceShaderAtomicFloatFeaturesEXT>(link);
                on(f.shaderBufferFloat32AtomicAdd, v.shaderBufferFloat32AtomicAdd);
                on(f.shaderImageFloat32AtomicAdd, v.shaderImageFloat32AtomicAdd);
                break;
            }
            default: break;   // VkPhysicalDeviceFeatures2 and anything the module does not use
        }
    }
    return f;
}

Status checkVulkanDeviceRequirements(uint32_t apiVersion, std::span<const std::string> enabledExtensions,
                                     const VulkanEnabledFeatures& features, bool requireRayTracing,
                                     std::string_view deviceName) {
    std::vector<std::string> missingExtensions, missingFeatures;
    auto enabled = [&](const char* name) {
        return std::find(enabledExtensions.begin(), enabledExtensions.end(), name) != enabledExtensions.end();
    };
    if (requireRayTracing)
        // The pipeline and acceleration-structure extensions, and the one the AS extension depends on.
        for (const char* e : {VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME, VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
                              VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME})
            if (!enabled(e)) missingExtensions.push_back(e);
    // Each feature with the reason the backend or the module's shaders need it.
    const std::pair<bool, const char*> needed[] = {
        {features.bufferDeviceAddress, "bufferDeviceAddress"},   // AS inputs, shader tables
        {features.runtimeDescriptorArray, "runtimeDescriptorArray"},   // scene texture array
        {features.shaderSampledImageArrayNonUniformIndexing, "shaderSampledImageArrayNonUniformIndexing"},   // nonuniformEXT in hit shaders
        {features.descriptorBindingPartiallyBound, "descriptorBindingPartiallyBound"},
        {features.timelineSemaphore, "timelineSemaphore"},   // the device fence
        {features.hostQueryReset, "hostQueryReset"},         // timestamp pools reset at creation
        {features.dynamicRendering, "dynamicRendering"},     // raster passes (no render passes)
        {features.synchronization2, "synchronization2"},     // every barrier and submit
    };
    for (const auto& [on, name] : needed)
        if (!on) missingFeatures.push_back(name);
    if (requireRayTracing) {
        if (!features.accelerationStructure) missingFeatures.push_back("accelerationStructure");
        if (!features.rayTracingPipeline) missingFeatures.push_back("rayTracingPipeline");
    }
    const bool versionOk = apiVersion >= VK_API_VERSION_1_3;
    if (versionOk && missingExtensions.empty() && missingFeatures.empty()) return okStatus();

    auto join = [](const std::vector<std::string>& names) {
        std::string out;
        for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
        return out;
    };
    std::string message = "vulkan: host device '" + std::string(deviceName) + "' cannot run the module:";
    std::string sep = " ";
    if (!versionOk) {
        message += sep + "API version " + std::to_string(VK_API_VERSION_MAJOR(apiVersion)) + "." +
                   std::to_string(VK_API_VERSION_MINOR(apiVersion)) + " (needs 1.3)";
        sep = "; ";
    }
    if (!missingExtensions.empty()) {
        message += sep + "missing extensions " + join(missingExtensions);
        sep = "; ";
    }
    if (!missingFeatures.empty()) message += sep + "missing features " + join(missingFeatures);
    return makeError(message);
}

}  // namespace caustics::rhi
