#pragma once
// Shared state of one Vulkan device: handles, properties, capabilities and its entry points (vk_dispatch.h).
// Every backend object holds a std::shared_ptr<VulkanContext>, so the VkDevice outlives its objects.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "caustics/rhi/device.h"
#include "vk_dispatch.h"

namespace caustics::rhi::vulkan {

class MemoryAllocator;
class DescriptorAllocator;

struct VulkanContext {
    VkInstance instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;      // graphics + compute (+ transfer) queue
    uint32_t queueFamily = 0;
    // False for a host engine's device (vk_device_wrap.cpp): the instance, device and queue are the
    // host's and are never destroyed here; only what this backend created is.
    bool ownsDevice = true;

    VkPhysicalDeviceProperties properties{};
    VkPhysicalDeviceMemoryProperties memoryProperties{};
    VkPhysicalDeviceRayTracingPipelinePropertiesKHR rayTracingProperties{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR};
    VkPhysicalDeviceAccelerationStructurePropertiesKHR accelStructProperties{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR};
    Capabilities capabilities;
    VulkanDispatch fn;   // every call of the backend goes through it

    std::unique_ptr<MemoryAllocator> allocator;          // see vk_memory.h
    std::unique_ptr<DescriptorAllocator> descriptors;    // see vk_binding.h
    std::function<void(LogLevel, std::string_view)> validationCallback;

    // Timeline semaphore that serves as the device fence (submit() signals ++lastSubmitted).
    VkSemaphore timeline = VK_NULL_HANDLE;
    uint64_t lastSubmitted = 0;

    VulkanContext();
    ~VulkanContext();   // destroys the device and instance (if owned) after all objects released their handles
    VulkanContext(const VulkanContext&) = delete;
    VulkanContext& operator=(const VulkanContext&) = delete;

    // Names an object for validation messages and captures (no-op without VK_EXT_debug_utils).
    void setName(VkObjectType type, uint64_t handle, std::string_view name) const;
    template <typename T>
    void setName(VkObjectType type, T handle, std::string_view name) const {
        setName(type, reinterpret_cast<uint64_t>(handle), name);
    }

    // The largest fence value the GPU has completed (queries the timeline semaphore).
    uint64_t completedValue() const;
    // Waits for all work this backend knows of: the whole device if it owns it, else every value of
    // the timeline handed out (a host's device may be busy with the host's own work on other queues).
    void waitForKnownWork();

    // Runs `destroy` once the GPU has finished every submission made so far (objects dropped while a
    // command list that uses them is in flight must not be destroyed at once). Thread-safe.
    void deferDestroy(std::function<void()> destroy);
    // Runs the deferred destructions whose submissions completed; `all` runs every one (device idle).
    void collectGarbage(bool all = false);

private:
    struct Deferred { uint64_t fence; std::function<void()> destroy; };
    std::mutex garbageMutex_;
    std::vector<Deferred> garbage_;
};
using ContextPtr = std::shared_ptr<VulkanContext>;

// "vkCreateBuffer failed (VK_ERROR_OUT_OF_DEVICE_MEMORY) for 'name'" as an Error.
Error vkError(VkResult result, std::string_view what, std::string_view objectName = {});
const char* vkResultName(VkResult result);

}  // namespace caustics::rhi::vulkan
