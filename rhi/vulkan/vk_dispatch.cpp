#include "vk_dispatch.h"

#include <string>

namespace caustics::rhi::vulkan {
namespace {

Status missingError(const std::string& missing, std::string_view level, std::string_view who) {
    if (missing.empty()) return okStatus();
    return makeError("vulkan: " + std::string(who) + ": its " + std::string(level) +
                     " proc-address function returned null for core entry points:" + missing);
}

}  // namespace

Status loadInstanceDispatch(VulkanDispatch& fn, PFN_vkGetInstanceProcAddr getInstanceProcAddr, VkInstance instance,
                            bool debugUtils, std::string_view who) {
    std::string missing;
#define CAUSTICS_VK_LOAD_REQUIRED(name)                                                        \
    fn.name = reinterpret_cast<PFN_##name>(getInstanceProcAddr(instance, #name));              \
    if (!fn.name) missing += " " #name;
    CAUSTICS_VK_INSTANCE_FUNCTIONS(CAUSTICS_VK_LOAD_REQUIRED)
#undef CAUSTICS_VK_LOAD_REQUIRED
    if (debugUtils) {
#define CAUSTICS_VK_LOAD_OPTIONAL(name) fn.name = reinterpret_cast<PFN_##name>(getInstanceProcAddr(instance, #name));
        CAUSTICS_VK_DEBUG_UTILS_FUNCTIONS(CAUSTICS_VK_LOAD_OPTIONAL)
#undef CAUSTICS_VK_LOAD_OPTIONAL
    }
    return missingError(missing, "vkGetInstanceProcAddr", who);
}

Status loadDeviceDispatch(VulkanDispatch& fn, VkDevice device, bool accelStruct, bool rayTracingPipeline,
                          std::string_view who) {
    if (!fn.vkGetDeviceProcAddr) return makeError("vulkan: " + std::string(who) + ": no vkGetDeviceProcAddr loaded");
    const PFN_vkGetDeviceProcAddr get = fn.vkGetDeviceProcAddr;
    std::string missing;
#define CAUSTICS_VK_LOAD_REQUIRED(name)                                                        \
    fn.name = reinterpret_cast<PFN_##name>(get(device, #name));                                \
    if (!fn.name) missing += " " #name;
    CAUSTICS_VK_DEVICE_FUNCTIONS(CAUSTICS_VK_LOAD_REQUIRED)
    if (accelStruct) { CAUSTICS_VK_ACCEL_STRUCT_FUNCTIONS(CAUSTICS_VK_LOAD_REQUIRED) }
    if (rayTracingPipeline) { CAUSTICS_VK_RAY_TRACING_PIPELINE_FUNCTIONS(CAUSTICS_VK_LOAD_REQUIRED) }
#undef CAUSTICS_VK_LOAD_REQUIRED
    return missingError(missing, "vkGetDeviceProcAddr", who);
}

}  // namespace caustics::rhi::vulkan
