#pragma once
// Embedding the module in a Vulkan engine: wrap the host's VkDevice (nothing is created but the
// module's own pools and allocations), import its images, buffers and TLAS with their current
// layouts, and record into its command buffers. Optional for hosts: the only public header that
// includes vulkan.h. Contract (ownership, threading, submission): docs/embedding.md "Device and resources".
#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "caustics/rhi/device.h"

namespace caustics::rhi {

// ---- The host's device -------------------------------------------------------------------------

// The device exactly as the host created it. The wrapped device never destroys any of these.
struct VulkanDeviceImport {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;   // graphics + compute queue; IDevice::submit and one-off uploads use it
    uint32_t queueFamily = 0;
    uint32_t apiVersion = 0;          // VkApplicationInfo::apiVersion the host created its instance with
    std::vector<std::string> enabledExtensions;                  // VkDeviceCreateInfo::ppEnabledExtensionNames
    std::vector<std::string> enabledInstanceExtensions;          // VK_EXT_debug_utils here: objects get names
    // VkDeviceCreateInfo::pNext: the feature chain (VkPhysicalDeviceFeatures2 or any feature structure
    // first), read once during wrapVulkanDevice.
    const void* enabledFeatures = nullptr;
    PFN_vkGetInstanceProcAddr getInstanceProcAddr = nullptr;     // the host's loader entry
    bool requireRayTracing = true;    // false: compute/raster only (refuses nothing about ray tracing)
    std::string debugName = "host device";
};

// The features the backend and the module's shaders use, as the host enabled them.
struct VulkanEnabledFeatures {
    bool bufferDeviceAddress = false;
    bool runtimeDescriptorArray = false;
    bool shaderSampledImageArrayNonUniformIndexing = false;
    bool descriptorBindingPartiallyBound = false;
    bool timelineSemaphore = false;
    bool hostQueryReset = false;
    bool dynamicRendering = false;
    bool synchronization2 = false;
    bool accelerationStructure = false;
    bool rayTracingPipeline = false;
    bool rayQuery = false;
    bool rayTracingPipelineTraceRaysIndirect = false;   // optional: ICommandList::dispatchRaysIndirect
    // Optional: without both the module takes its fixed-point accumulation path.
    bool shaderBufferFloat32AtomicAdd = false;
    bool shaderImageFloat32AtomicAdd = false;
};

// Reads a VkDeviceCreateInfo::pNext feature chain: VkPhysicalDeviceVulkan12/13Features
// and the per-extension structures (buffer device address, descriptor indexing, timeline semaphore,
// host query reset, dynamic rendering, synchronization2, AS, RT pipeline, ray query, atomic float).
// Device-free; unknown structures are skipped. `chain` may be any structure of the chain or null.
VulkanEnabledFeatures readVulkanFeatureChain(const void* chain);

// ok, or ONE error naming every missing API version, extension and feature, e.g.
// "vulkan: host device 'X' cannot run the module: missing extensions VK_KHR_ray_tracing_pipeline,
// VK_KHR_acceleration_structure; missing features rayTracingPipeline, accelerationStructure". Device-free.
Status checkVulkanDeviceRequirements(uint32_t apiVersion, std::span<const std::string> enabledExtensions,
                                     const VulkanEnabledFeatures& features, bool requireRayTracing,
                                     std::string_view deviceName);

// Wraps the host's device. Creates no instance or device; creates only the module's own timeline
// semaphore, memory blocks and descriptor pools, and destroys those (and only those) when the last
// handle goes. Refuses a device that lacks a requirement (checkVulkanDeviceRequirements).
Result<DeviceHandle> wrapVulkanDevice(const VulkanDeviceImport& desc);

// ---- The host's resources ----------------------------------------------------------------------

// A host image. `uses` is what the module will do with it; each use must be allowed by `usage`
// (Storage needs VK_IMAGE_USAGE_STORAGE_BIT and a format with storage-image support, Sampled needs
// SAMPLED, RenderTarget COLOR_ATTACHMENT, DepthStencil DEPTH_STENCIL_ATTACHMENT, Copy* TRANSFER_*),
// otherwise the import fails naming the texture and the problem.
struct VulkanTextureImport {
    VkImage image = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkImageUsageFlags usage = 0;      // VkImageCreateInfo::usage
    uint32_t width = 0, height = 0;
    uint32_t arrayLayers = 1, mipLevels = 1;
    bool cube = false;                // created CUBE_COMPATIBLE and meant to be sampled as a cube
    TextureUsage uses = TextureUsage::Sampled;
    std::string debugName;
};
// The imported texture does not own the image; views it makes for itself are its own.
Result<TextureHandle> importVulkanTexture(IDevice& device, const VulkanTextureImport& desc);

// The RHI state whose Vulkan translation is exactly `layout` (for RenderGraph::importTexture's
// current and final states), or an error naming a layout the RHI cannot reproduce. Depth images are
// read in DEPTH_STENCIL_READ_ONLY_OPTIMAL (not SHADER_READ_ONLY_OPTIMAL). Device-free.
Result<ResourceState> resourceStateFromVkImageLayout(VkImageLayout layout, bool isDepthFormat = false);

struct VulkanBufferImport {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceSize byteSize = 0;
    VkBufferUsageFlags usage = 0;     // VkBufferCreateInfo::usage
    VkDeviceAddress deviceAddress = 0;// 0: queried when usage has SHADER_DEVICE_ADDRESS
    BufferUsage uses = BufferUsage::Storage;   // checked against `usage` like VulkanTextureImport::uses
    uint32_t structStride = 0;
    std::string debugName;
};
Result<BufferHandle> importVulkanBuffer(IDevice& device, const VulkanBufferImport& desc);

// The host's acceleration structure (usually its TLAS), bindable as BindingType::AccelStruct.
struct VulkanAccelStructImport {
    VkAccelerationStructureKHR accelStruct = VK_NULL_HANDLE;
    VkDeviceAddress deviceAddress = 0;   // 0: queried with vkGetAccelerationStructureDeviceAddressKHR
    bool isTopLevel = true;
    std::string debugName;
};
Result<AccelStructHandle> importVulkanAccelStruct(IDevice& device, const VulkanAccelStructImport& desc);

// ---- The host's command buffer -----------------------------------------------------------------

struct VulkanCommandBufferImport {
    VkCommandBuffer commandBuffer = VK_NULL_HANDLE;   // begun by the host, on `queueFamily` of the device
    // Timestamps write into the module's own query pool (reset with vkCmdResetQueryPool inside this
    // command buffer). false: writeTimestamp/resetTimestamps record nothing and per-pass times stay empty.
    bool allowTimestamps = true;
    std::string debugName = "host command buffer";
};
// An ICommandList that records into the host's command buffer. begin() and end() record nothing:
// the host begins, ends, submits and resets the buffer. Staging/scratch buffers the list allocates
// live until the list is destroyed, or, after vulkanSubmitSignal, until that signal is reached.
Result<CommandListHandle> wrapVulkanCommandBuffer(IDevice& device, const VulkanCommandBufferImport& desc);

// A timeline semaphore value for the host to signal in the vkQueueSubmit that executes `wrapped`:
// the device then knows when that work completes (deferred destruction of objects dropped meanwhile,
// waitForFence, release of the list's staging buffers). Call once per recording, before submitting.
struct VulkanSubmitSignal {
    VkSemaphore semaphore = VK_NULL_HANDLE;
    uint64_t value = 0;
};
Result<VulkanSubmitSignal> vulkanSubmitSignal(IDevice& device, ICommandList& wrapped);

}  // namespace caustics::rhi
