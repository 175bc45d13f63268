#pragma once
// Every Vulkan entry point the backend calls, in one table per device (docs/embedding.md, "Device and
// resources"). The table is loaded through the vkGetInstanceProcAddr of whoever made the instance: the
// host's for a wrapped device (so a host using volk, its own layer dispatch or an interposer sees every
// call of the module), the loader's for our own. Device-level entries come from vkGetDeviceProcAddr,
// itself fetched through that vkGetInstanceProcAddr. Only the pre-instance global functions
// (vkCreateInstance, vkEnumerateInstance*Properties; vk_instance.cpp) are called through the loader.
#include <vulkan/vulkan.h>

#include "caustics/rhi/result.h"

namespace caustics::rhi::vulkan {

// Instance-level core functions (Vulkan 1.0-1.1).
#define CAUSTICS_VK_INSTANCE_FUNCTIONS(X)                                                                   \
    X(vkDestroyInstance) X(vkEnumeratePhysicalDevices) X(vkGetPhysicalDeviceProperties)                      \
    X(vkGetPhysicalDeviceProperties2) X(vkGetPhysicalDeviceMemoryProperties)                                 \
    X(vkGetPhysicalDeviceFormatProperties) X(vkGetPhysicalDeviceFeatures2)                                  \
    X(vkGetPhysicalDeviceQueueFamilyProperties) X(vkEnumerateDeviceExtensionProperties) X(vkCreateDevice)    \
    X(vkGetDeviceProcAddr)

// VK_EXT_debug_utils (an instance extension; null without it).
#define CAUSTICS_VK_DEBUG_UTILS_FUNCTIONS(X)                                                                \
    X(vkCreateDebugUtilsMessengerEXT) X(vkDestroyDebugUtilsMessengerEXT) X(vkSetDebugUtilsObjectNameEXT)     \
    X(vkCmdBeginDebugUtilsLabelEXT) X(vkCmdEndDebugUtilsLabelEXT)

// Device-level core functions (Vulkan 1.0-1.3: dynamic rendering, synchronization2, timeline
// semaphores, buffer device address and host query reset are core in 1.3).
#define CAUSTICS_VK_DEVICE_FUNCTIONS(X)                                                                     \
    X(vkDestroyDevice) X(vkGetDeviceQueue) X(vkDeviceWaitIdle) X(vkQueueSubmit2) X(vkQueueWaitIdle)          \
    X(vkAllocateMemory) X(vkFreeMemory) X(vkMapMemory) X(vkBindBufferMemory) X(vkBindImageMemory)            \
    X(vkGetBufferMemoryRequirements) X(vkGetImageMemoryRequirements) X(vkGetBufferDeviceAddress)             \
    X(vkCreateBuffer) X(vkDestroyBuffer) X(vkCreateImage) X(vkDestroyImage) X(vkCreateImageView)             \
    X(vkDestroyImageView) X(vkCreateSampler) X(vkDestroySampler) X(vkCreateShaderModule)                     \
    X(vkDestroyShaderModule) X(vkCreatePipelineLayout) X(vkDestroyPipelineLayout)                            \
    X(vkCreateComputePipelines) X(vkCreateGraphicsPipelines) X(vkDestroyPipeline)                            \
    X(vkCreateDescriptorSetLayout) X(vkDestroyDescriptorSetLayout) X(vkCreateDescriptorPool)                 \
    X(vkDestroyDescriptorPool) X(vkAllocateDescriptorSets) X(vkFreeDescriptorSets) X(vkUpdateDescriptorSets) \
    X(vkCreateCommandPool) X(vkDestroyCommandPool) X(vkAllocateCommandBuffers) X(vkResetCommandBuffer)       \
    X(vkBeginCommandBuffer) X(vkEndCommandBuffer) X(vkCreateSemaphore) X(vkDestroySemaphore)                 \
    X(vkGetSemaphoreCounterValue) X(vkWaitSemaphores) X(vkCreateQueryPool) X(vkDestroyQueryPool)             \
    X(vkResetQueryPool) X(vkGetQueryPoolResults)                                                             \
    X(vkCmdBindPipeline) X(vkCmdBindDescriptorSets) X(vkCmdPushConstants) X(vkCmdDispatch) X(vkCmdDraw)      \
    X(vkCmdDispatchIndirect) X(vkCmdDrawIndexed) X(vkCmdBindVertexBuffers) X(vkCmdBindIndexBuffer) X(vkCmdSetViewport)                \
    X(vkCmdSetScissor) X(vkCmdBeginRendering) X(vkCmdEndRendering) X(vkCmdPipelineBarrier)                  \
    X(vkCmdPipelineBarrier2) X(vkCmdCopyBuffer) X(vkCmdCopyImage) X(vkCmdCopyBufferToImage)                  \
    X(vkCmdCopyImageToBuffer) X(vkCmdUpdateBuffer) X(vkCmdFillBuffer) X(vkCmdClearColorImage)                \
    X(vkCmdClearDepthStencilImage) X(vkCmdResetQueryPool) X(vkCmdWriteTimestamp2)

// VK_KHR_acceleration_structure (null when not enabled).
#define CAUSTICS_VK_ACCEL_STRUCT_FUNCTIONS(X)                                                               \
    X(vkCreateAccelerationStructureKHR) X(vkDestroyAccelerationStructureKHR)                                 \
    X(vkGetAccelerationStructureBuildSizesKHR) X(vkCmdBuildAccelerationStructuresKHR)                        \
    X(vkGetAccelerationStructureDeviceAddressKHR) X(vkCmdWriteAccelerationStructuresPropertiesKHR)           \
    X(vkCmdCopyAccelerationStructureKHR)

// VK_KHR_ray_tracing_pipeline (null when not enabled).
#define CAUSTICS_VK_RAY_TRACING_PIPELINE_FUNCTIONS(X)                                                       \
    X(vkCreateRayTracingPipelinesKHR) X(vkGetRayTracingShaderGroupHandlesKHR) X(vkCmdTraceRaysKHR)           \
    X(vkCmdTraceRaysIndirectKHR)

struct VulkanDispatch {
#define CAUSTICS_VK_MEMBER(name) PFN_##name name = nullptr;
    CAUSTICS_VK_INSTANCE_FUNCTIONS(CAUSTICS_VK_MEMBER)
    CAUSTICS_VK_DEBUG_UTILS_FUNCTIONS(CAUSTICS_VK_MEMBER)
    CAUSTICS_VK_DEVICE_FUNCTIONS(CAUSTICS_VK_MEMBER)
    CAUSTICS_VK_ACCEL_STRUCT_FUNCTIONS(CAUSTICS_VK_MEMBER)
    CAUSTICS_VK_RAY_TRACING_PIPELINE_FUNCTIONS(CAUSTICS_VK_MEMBER)
#undef CAUSTICS_VK_MEMBER
};

// The instance-level entries (and VK_EXT_debug_utils' when `debugUtils`) through getInstanceProcAddr;
// an error naming every core function it did not return. `who` names the instance's owner in it.
Status loadInstanceDispatch(VulkanDispatch& fn, PFN_vkGetInstanceProcAddr getInstanceProcAddr, VkInstance instance,
                            bool debugUtils, std::string_view who);
// The device-level entries through fn.vkGetDeviceProcAddr (loadInstanceDispatch first): every core one
// (an error names each missing), the extension ones only where enabled.
Status loadDeviceDispatch(VulkanDispatch& fn, VkDevice device, bool accelStruct, bool rayTracingPipeline,
                          std::string_view who);

}  // namespace caustics::rhi::vulkan
