#include "vk_context.h"

#include <string>

#include "vk_binding.h"
#include "vk_memory.h"

namespace caustics::rhi::vulkan {

VulkanContext::VulkanContext() = default;

VulkanContext::~VulkanContext() {
    if (device != VK_NULL_HANDLE) {
        waitForKnownWork();
        collectGarbage(true);
        descriptors.reset();
        allocator.reset();
        if (timeline != VK_NULL_HANDLE) fn.vkDestroySemaphore(device, timeline, nullptr);
        if (ownsDevice) fn.vkDestroyDevice(device, nullptr);
    }
    if (!ownsDevice) return;
    if (messenger != VK_NULL_HANDLE && fn.vkDestroyDebugUtilsMessengerEXT)
        fn.vkDestroyDebugUtilsMessengerEXT(instance, messenger, nullptr);
    if (instance != VK_NULL_HANDLE) fn.vkDestroyInstance(instance, nullptr);
}

void VulkanContext::setName(VkObjectType type, uint64_t handle, std::string_view name) const {
    if (!fn.vkSetDebugUtilsObjectNameEXT || name.empty() || handle == 0) return;
    std::string terminated(name);
    VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = terminated.c_str();
    fn.vkSetDebugUtilsObjectNameEXT(device, &info);
}

uint64_t VulkanContext::completedValue() const {
    uint64_t value = 0;
    if (timeline != VK_NULL_HANDLE) fn.vkGetSemaphoreCounterValue(device, timeline, &value);
    return value;
}

void VulkanContext::waitForKnownWork() {
    if (device == VK_NULL_HANDLE) return;
    if (ownsDevice) {
        fn.vkDeviceWaitIdle(device);
        return;
    }
    if (timeline == VK_NULL_HANDLE) return;
    uint64_t value;
    {
        std::lock_guard lock(garbageMutex_);
        value = lastSubmitted;
    }
    VkSemaphoreWaitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_WAIT_INFO};
    wait.semaphoreCount = 1;
    wait.pSemaphores = &timeline;
    wait.pValues = &value;
    fn.vkWaitSemaphores(device, &wait, UINT64_MAX);
}

void VulkanContext::deferDestroy(std::function<void()> destroy) {
    uint64_t fence;
    {
        std::lock_guard lock(garbageMutex_);
        fence = lastSubmitted;
    }
    if (fence == 0 || completedValue() >= fence) {
        destroy();
        return;
    }
    std::lock_guard lock(garbageMutex_);
    garbage_.push_back({fence, std::move(destroy)});
}

void VulkanContext::collectGarbage(bool all) {
    std::vector<Deferred> ready;
    {
        uint64_t done = all ? ~0ull : completedValue();
        std::lock_guard lock(garbageMutex_);
        for (size_t i = 0; i < garbage_.size();) {
            if (garbage_[i].fence <= done) {
                ready.push_back(std::move(garbage_[i]));
                garbage_[i] = std::move(garbage_.back());
                garbage_.pop_back();
            } else {
                ++i;
            }
        }
    }
    // Outside the lock: a destructor may defer further work.
    for (Deferred& d : ready) d.destroy();
}

const char* vkResultName(VkResult result) {
    switch (result) {
        case VK_SUCCESS: return "VK_SUCCESS";
        case VK_NOT_READY: return "VK_NOT_READY";
        case VK_TIMEOUT: return "VK_TIMEOUT";
        case VK_ERROR_OUT_OF_HOST_MEMORY: return "VK_ERROR_OUT_OF_HOST_MEMORY";
        case VK_ERROR_OUT_OF_DEVICE_MEMORY: return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
        case VK_ERROR_INITIALIZATION_FAILED: return "VK_ERROR_INITIALIZATION_FAILED";
        case VK_ERROR_DEVICE_LOST: return "VK_ERROR_DEVICE_LOST";
        case VK_ERROR_MEMORY_MAP_FAILED: return "VK_ERROR_MEMORY_MAP_FAILED";
        case VK_ERROR_LAYER_NOT_PRESENT: return "VK_ERROR_LAYER_NOT_PRESENT";
        case VK_ERROR_EXTENSION_NOT_PRESENT: return "VK_ERROR_EXTENSION_NOT_PRESENT";
        case VK_ERROR_FEATURE_NOT_PRESENT: return "VK_ERROR_FEATURE_NOT_PRESENT";
        case VK_ERROR_INCOMPATIBLE_DRIVER: return "VK_ERROR_INCOMPATIBLE_DRIVER";
        case VK_ERROR_TOO_MANY_OBJECTS: return "VK_ERROR_TOO_MANY_OBJECTS";
        case VK_ERROR_FORMAT_NOT_SUPPORTED: return "VK_ERROR_FORMAT_NOT_SUPPORTED";
        case VK_ERROR_FRAGMENTED_POOL: return "VK_ERROR_FRAGMENTED_POOL";
        case VK_ERROR_OUT_OF_POOL_MEMORY: return "VK_ERROR_OUT_OF_POOL_MEMORY";
        case VK_ERROR_INVALID_SHADER_NV: return "VK_ERROR_INVALID_SHADER_NV";
        default: return "VkResult(?)";
    }
}

Error vkError(VkResult result, std::string_view what, std::string_view objectName) {
    std::string message = "vulkan: " + std::string(what) + " failed (" + vkResultName(result) + ", " +
                          std::to_string(int(result)) + ")";
    if (!objectName.empty()) message += " for '" + std::string(objectName) + "'";
    return makeError(std::move(message));
}

}  // namespace caustics::rhi::vulkan
