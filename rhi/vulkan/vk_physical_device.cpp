// Physical-device choice and VkDevice creation: a device is refused with a message naming the first
// missing extension or feature and the device.
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include "vk_device_setup.h"
#include "vk_instance.h"

namespace caustics::rhi::vulkan {
namespace {

struct FeatureChain {
    VkPhysicalDeviceFeatures2 base{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceAccelerationStructureFeaturesKHR as{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
    VkPhysicalDeviceRayTracingPipelineFeaturesKHR rt{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
    VkPhysicalDeviceRayQueryFeaturesKHR rayQuery{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
    VkPhysicalDeviceShaderAtomicFloatFeaturesEXT atomicFloat{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_ATOMIC_FLOAT_FEATURES_EXT};

    // Links only the structures whose extensions are enabled/present (spec: pNext structs of absent
    // extensions are invalid).
    void link(bool withAs, bool withRt, bool withRayQuery, bool withAtomicFloat) {
        void** next = &base.pNext;
        auto append = [&](auto& s) { *next = &s; next = &s.pNext; };
        append(v12);
        append(v13);
        if (withAs) append(as);
        if (withRt) append(rt);
        if (withRayQuery) append(rayQuery);
        if (withAtomicFloat) append(atomicFloat);
        *next = nullptr;
    }
};

struct Candidate {
    VkPhysicalDevice device = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;
    std::set<std::string> extensions;
    FeatureChain features;
};

// Returns an empty string when `physical` fits, otherwise why not.
std::string evaluate(const VulkanContext& context, VkPhysicalDevice physical, const DeviceDesc& desc, Candidate& out) {
    VkPhysicalDeviceProperties props;
    context.fn.vkGetPhysicalDeviceProperties(physical, &props);
    const std::string name = props.deviceName;
    auto refuse = [&](const std::string& what, const char* by) {
        return "vulkan: device '" + name + "' lacks " + what + " required by " + by;
    };
    if (props.apiVersion < VK_API_VERSION_1_3) return refuse("Vulkan 1.3", "the vulkan backend");

    uint32_t count = 0;
    context.fn.vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> exts(count);
    context.fn.vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, exts.data());
    out.extensions.clear();
    for (const auto& e : exts) out.extensions.insert(e.extensionName);
    auto has = [&](const char* e) { return out.extensions.count(e) != 0; };

    for (const std::string& e : desc.requiredExtensions)
        if (!out.extensions.count(e)) return refuse(e, "DeviceDesc::requiredExtensions");
    if (desc.requireRayTracing)
        for (const char* e : {VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME, VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
                              VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME})
            if (!has(e)) return refuse(e, "DeviceDesc::requireRayTracing");

    const bool asExt = has(VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME) && has(VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME);
    const bool rtExt = asExt && has(VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME);
    out.features.link(asExt, rtExt, asExt && has(VK_KHR_RAY_QUERY_EXTENSION_NAME),
                      has(VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME));
    context.fn.vkGetPhysicalDeviceFeatures2(physical, &out.features.base);
    const auto& f12 = out.features.v12;
    const auto& f13 = out.features.v13;
    const std::pair<VkBool32, const char*> core[] = {
        {f12.bufferDeviceAddress, "bufferDeviceAddress"},
        {f12.descriptorIndexing, "descriptorIndexing"},
        {f12.runtimeDescriptorArray, "runtimeDescriptorArray"},
        {f12.shaderSampledImageArrayNonUniformIndexing, "shaderSampledImageArrayNonUniformIndexing"},
        {f12.descriptorBindingPartiallyBound, "descriptorBindingPartiallyBound"},
        {f12.scalarBlockLayout, "scalarBlockLayout"},
        {f12.timelineSemaphore, "timelineSemaphore"},
        {f12.hostQueryReset, "hostQueryReset"},
        {f13.dynamicRendering, "dynamicRendering"},
        {f13.synchronization2, "synchronization2"},
    };
    for (const auto& [supported, feature] : core)
        if (!supported) return refuse(std::string("the feature ") + feature, "the vulkan backend");
    if (desc.requireRayTracing) {
        if (!out.features.rt.rayTracingPipeline) return refuse("the feature rayTracingPipeline", "DeviceDesc::requireRayTracing");
        if (!out.features.as.accelerationStructure)
            return refuse("the feature accelerationStructure", "DeviceDesc::requireRayTracing");
    }

    uint32_t familyCount = 0;
    context.fn.vkGetPhysicalDeviceQueueFamilyProperties(physical, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    context.fn.vkGetPhysicalDeviceQueueFamilyProperties(physical, &familyCount, families.data());
    for (uint32_t i = 0; i < familyCount; ++i) {
        const VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
        if ((families[i].queueFlags & need) == need && families[i].timestampValidBits > 0) {
            out.device = physical;
            out.queueFamily = i;
            return {};
        }
    }
    return refuse("a graphics+compute queue with timestamps", "the vulkan backend");
}

}  // namespace

Status createLogicalDevice(VulkanContext& context, const DeviceDesc& desc) {
    uint32_t count = 0;
    context.fn.vkEnumeratePhysicalDevices(context.instance, &count, nullptr);
    std::vector<VkPhysicalDevice> physicals(count);
    context.fn.vkEnumeratePhysicalDevices(context.instance, &count, physicals.data());
    if (physicals.empty()) return makeError("vulkan: no physical device (is a Vulkan driver installed?)");

    Candidate chosen;
    std::string reasons;
    for (uint32_t i = 0; i < count; ++i) {
        if (desc.adapterIndex && *desc.adapterIndex != i) continue;
        std::string why = evaluate(context, physicals[i], desc, chosen);
        if (why.empty()) break;
        chosen.device = VK_NULL_HANDLE;
        reasons += (reasons.empty() ? "" : "; ") + why;
    }
    if (chosen.device == VK_NULL_HANDLE)
        return makeError(reasons.empty() ? "vulkan: adapterIndex " + std::to_string(*desc.adapterIndex) + " does not exist"
                                         : reasons);

    auto has = [&](const char* e) { return chosen.extensions.count(e) != 0; };
    const bool asExt = has(VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME) && has(VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME) &&
                       chosen.features.as.accelerationStructure;
    const bool rtExt = asExt && has(VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME) && chosen.features.rt.rayTracingPipeline;
    const bool rayQuery = asExt && has(VK_KHR_RAY_QUERY_EXTENSION_NAME) && chosen.features.rayQuery.rayQuery;
    const bool atomicFloat = has(VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME);

    std::vector<const char*> extensions;
    for (const std::string& e : desc.requiredExtensions) extensions.push_back(e.c_str());
    auto add = [&](const char* e) {
        for (const char* x : extensions)
            if (std::strcmp(x, e) == 0) return;
        extensions.push_back(e);
    };
    if (asExt) {
        add(VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME);
        add(VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME);
    }
    if (rtExt) add(VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME);
    if (rayQuery) add(VK_KHR_RAY_QUERY_EXTENSION_NAME);
    if (atomicFloat) add(VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME);

    // Enable exactly what the backend relies on (plus what is supported of a few common shader features).
    const FeatureChain& s = chosen.features;
    FeatureChain e;
    e.link(asExt, rtExt, rayQuery, atomicFloat);
    e.base.features.shaderInt64 = s.base.features.shaderInt64;
    e.base.features.fragmentStoresAndAtomics = s.base.features.fragmentStoresAndAtomics;
    e.base.features.vertexPipelineStoresAndAtomics = s.base.features.vertexPipelineStoresAndAtomics;
    e.base.features.shaderStorageImageReadWithoutFormat = s.base.features.shaderStorageImageReadWithoutFormat;
    e.base.features.shaderStorageImageWriteWithoutFormat = s.base.features.shaderStorageImageWriteWithoutFormat;
    e.base.features.imageCubeArray = s.base.features.imageCubeArray;
    e.v12.bufferDeviceAddress = VK_TRUE;
    e.v12.descriptorIndexing = VK_TRUE;
    e.v12.runtimeDescriptorArray = VK_TRUE;
    e.v12.shaderSampledImageArrayNonUniformIndexing = VK_TRUE;
    e.v12.shaderStorageBufferArrayNonUniformIndexing = s.v12.shaderStorageBufferArrayNonUniformIndexing;
    e.v12.descriptorBindingPartiallyBound = VK_TRUE;
    e.v12.scalarBlockLayout = VK_TRUE;
    e.v12.timelineSemaphore = VK_TRUE;
    e.v12.hostQueryReset = VK_TRUE;
    e.v12.vulkanMemoryModel = s.v12.vulkanMemoryModel;
    e.v12.vulkanMemoryModelDeviceScope = s.v12.vulkanMemoryModelDeviceScope;
    e.v12.shaderInt8 = s.v12.shaderInt8;
    e.v12.shaderBufferInt64Atomics = s.v12.shaderBufferInt64Atomics && s.base.features.shaderInt64;
    e.v12.storageBuffer8BitAccess = s.v12.storageBuffer8BitAccess;
    e.v13.dynamicRendering = VK_TRUE;
    e.v13.synchronization2 = VK_TRUE;
    e.v13.maintenance4 = s.v13.maintenance4;
    e.as.accelerationStructure = asExt;
    e.rt.rayTracingPipeline = rtExt;
    e.rt.rayTracingPipelineTraceRaysIndirect = rtExt && s.rt.rayTracingPipelineTraceRaysIndirect;
    e.rayQuery.rayQuery = rayQuery;
    e.atomicFloat.shaderBufferFloat32AtomicAdd = s.atomicFloat.shaderBufferFloat32AtomicAdd;
    e.atomicFloat.shaderImageFloat32AtomicAdd = s.atomicFloat.shaderImageFloat32AtomicAdd;
    e.atomicFloat.shaderBufferFloat32Atomics = s.atomicFloat.shaderBufferFloat32Atomics;
    e.atomicFloat.shaderImageFloat32Atomics = s.atomicFloat.shaderImageFloat32Atomics;

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue.queueFamilyIndex = chosen.queueFamily;
    queue.queueCount = 1;
    queue.pQueuePriorities = &priority;
    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.pNext = &e.base;
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queue;
    info.enabledExtensionCount = uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VkResult r = context.fn.vkCreateDevice(chosen.device, &info, nullptr, &context.device);
    if (r != VK_SUCCESS) return vkError(r, "vkCreateDevice");

    context.physicalDevice = chosen.device;
    context.queueFamily = chosen.queueFamily;
    CAUSTICS_CHECK(loadDeviceDispatch(context.fn, context.device, asExt, rtExt, "our device"));
    context.fn.vkGetDeviceQueue(context.device, chosen.queueFamily, 0, &context.queue);
    return finishDeviceSetup(context, {asExt, rtExt, rayQuery,
                                       atomicFloat && s.atomicFloat.shaderBufferFloat32AtomicAdd &&
                                           s.atomicFloat.shaderImageFloat32AtomicAdd,
                                       rtExt && s.rt.rayTracingPipelineTraceRaysIndirect,
                                       s.v12.shaderBufferInt64Atomics && s.base.features.shaderInt64});
}

}  // namespace caustics::rhi::vulkan
