#pragma once
// A minimal host engine in raw Vulkan (no RHI): its own instance with the validation layer
// (synchronization validation on, like tests/gpu/support/gpu_test.*), device, queue, command buffer,
// images and buffers. The embedding tests wrap it with vulkan_interop.h. Every WARNING/ERROR message
// of the layer is collected; the tests fail on any.
#include <vulkan/vulkan.h>

#include <mutex>
#include <string>
#include <vector>

#include "caustics/rhi/vulkan_interop.h"

namespace caustics::test {

struct RawImage {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
};
struct RawBuffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    void* mapped = nullptr;   // host-visible, coherent
};

class RawVulkanHost {
public:
    // withRayTracing: enable VK_KHR_ray_tracing_pipeline, VK_KHR_acceleration_structure and their
    // features. Returns false (with why()) where the instance or device cannot be made.
    bool create(bool withRayTracing);
    ~RawVulkanHost() { destroyAll(); }
    // Destroys everything it made, the device last: the layer reports objects left on the device
    // (e.g. anything a wrapped RHI device forgot) there, into messages().
    void destroyAll();
    const std::string& why() const { return why_; }

    // What wrapVulkanDevice needs, exactly as created.
    rhi::VulkanDeviceImport deviceImport() const;

    RawImage createImage(uint32_t width, uint32_t height, VkFormat format, VkImageUsageFlags usage);
    RawBuffer createHostBuffer(VkDeviceSize bytes, VkBufferUsageFlags usage);
    void destroy(RawImage& image);
    void destroy(RawBuffer& buffer);

    // Begins the host's command buffer (one-time submit).
    void begin();
    // Ends it and submits on the host's queue, signalling `signal` too when given; waits on a host fence.
    bool endSubmitAndWait(const rhi::VulkanSubmitSignal* signal = nullptr);
    // A raw image barrier of the whole colour image.
    void imageBarrier(VkImage image, VkImageLayout oldLayout, VkImageLayout newLayout, VkPipelineStageFlags2 srcStage,
                      VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess);

    // A raw global memory barrier (e.g. copy writes -> host reads, AS build writes -> AS reads).
    void memoryBarrier(VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage,
                       VkAccessFlags2 dstAccess);

    std::vector<std::string> messages();

    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;
    VkCommandPool pool = VK_NULL_HANDLE;
    VkCommandBuffer commandBuffer = VK_NULL_HANDLE;

private:
    static VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);
    uint32_t memoryType(uint32_t typeBits, VkMemoryPropertyFlags properties) const;
    bool fail(std::string why) { why_ = std::move(why); return false; }

    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
    std::vector<std::string> extensions_;
    // Feature chain given to vkCreateDevice; kept so deviceImport() can hand it over.
    VkPhysicalDeviceFeatures2 features_{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    VkPhysicalDeviceVulkan12Features features12_{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceVulkan13Features features13_{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceAccelerationStructureFeaturesKHR accelFeatures_{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
    VkPhysicalDeviceRayTracingPipelineFeaturesKHR rtFeatures_{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
    std::mutex mutex_;
    std::vector<std::string> messages_;
    std::string why_;
};

}  // namespace caustics::test
