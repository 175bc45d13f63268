#include "raw_vulkan_host.h"

#include <cstring>

namespace caustics::test {

VKAPI_ATTR VkBool32 VKAPI_CALL RawVulkanHost::onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                        VkDebugUtilsMessageTypeFlagsEXT,
                                                        const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    // INFO lines are the layer's status; warnings and errors fail the tests.
    if (!(severity & (VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT)))
        return VK_FALSE;
    auto* host = static_cast<RawVulkanHost*>(user);
    std::lock_guard lock(host->mutex_);
    host->messages_.push_back(std::string(data->pMessageIdName ? data->pMessageIdName : "") + ": " +
                              (data->pMessage ? data->pMessage : ""));
    return VK_FALSE;
}

bool RawVulkanHost::create(bool withRayTracing) {
    const char* layer = "VK_LAYER_KHRONOS_validation";
    const char* instanceExtensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME};
    VkDebugUtilsMessengerCreateInfoEXT messenger{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messenger.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messenger.pfnUserCallback = onMessage;
    messenger.pUserData = this;
    const VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    VkValidationFeaturesEXT validation{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    validation.enabledValidationFeatureCount = 1;
    validation.pEnabledValidationFeatures = enables;
    validation.pNext = &messenger;
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "raw vulkan host";
    app.apiVersion = VK_API_VERSION_1_3;
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pNext = &validation;
    info.pApplicationInfo = &app;
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = &layer;
    info.enabledExtensionCount = 2;
    info.ppEnabledExtensionNames = instanceExtensions;
    if (vkCreateInstance(&info, nullptr, &instance) != VK_SUCCESS) return fail("vkCreateInstance with validation failed");
    auto createMessenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    messenger.pNext = nullptr;
    if (!createMessenger || createMessenger(instance, &messenger, nullptr, &messenger_) != VK_SUCCESS)
        return fail("vkCreateDebugUtilsMessengerEXT failed");

    uint32_t count = 0;
    vkEnumeratePhysicalDevices(instance, &count, nullptr);
    if (count == 0) return fail("no physical device");
    std::vector<VkPhysicalDevice> physicals(count);
    vkEnumeratePhysicalDevices(instance, &count, physicals.data());
    physicalDevice = physicals[0];
    uint32_t families = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &families, nullptr);
    std::vector<VkQueueFamilyProperties> props(families);
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &families, props.data());
    bool found = false;
    for (uint32_t i = 0; i < families && !found; ++i)
        if ((props[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) && (props[i].queueFlags & VK_QUEUE_COMPUTE_BIT)) {
            queueFamily = i;
            found = true;
        }
    if (!found) return fail("no graphics+compute queue family");

    // Exactly the features the module documents as required (docs/embedding.md), nothing more.
    features12_.bufferDeviceAddress = VK_TRUE;
    features12_.runtimeDescriptorArray = VK_TRUE;
    features12_.shaderSampledImageArrayNonUniformIndexing = VK_TRUE;
    features12_.descriptorBindingPartiallyBound = VK_TRUE;
    features12_.timelineSemaphore = VK_TRUE;
    features12_.hostQueryReset = VK_TRUE;
    features13_.dynamicRendering = VK_TRUE;
    features13_.synchronization2 = VK_TRUE;
    features_.pNext = &features12_;
    features12_.pNext = &features13_;
    features13_.pNext = nullptr;
    if (withRayTracing) {
        extensions_ = {VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME, VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
                       VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME};
        accelFeatures_.accelerationStructure = VK_TRUE;
        rtFeatures_.rayTracingPipeline = VK_TRUE;
        features13_.pNext = &accelFeatures_;
        accelFeatures_.pNext = &rtFeatures_;
        rtFeatures_.pNext = nullptr;
    }
    std::vector<const char*> names;
    for (const std::string& e : extensions_) names.push_back(e.c_str());
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = queueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    deviceInfo.pNext = &features_;
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;
    deviceInfo.enabledExtensionCount = uint32_t(names.size());
    deviceInfo.ppEnabledExtensionNames = names.data();
    if (vkCreateDevice(physicalDevice, &deviceInfo, nullptr, &device) != VK_SUCCESS) return fail("vkCreateDevice failed");
    vkGetDeviceQueue(device, queueFamily, 0, &queue);

    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = queueFamily;
    if (vkCreateCommandPool(device, &poolInfo, nullptr, &pool) != VK_SUCCESS) return fail("vkCreateCommandPool failed");
    VkCommandBufferAllocateInfo allocInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocInfo.commandPool = pool;
    allocInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocInfo.commandBufferCount = 1;
    if (vkAllocateCommandBuffers(device, &allocInfo, &commandBuffer) != VK_SUCCESS)
        return fail("vkAllocateCommandBuffers failed");
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    if (vkCreateFence(device, &fenceInfo, nullptr, &fence_) != VK_SUCCESS) return fail("vkCreateFence failed");
    return true;
}

void RawVulkanHost::destroyAll() {
    if (device != VK_NULL_HANDLE) {
        vkDeviceWaitIdle(device);
        if (fence_) vkDestroyFence(device, fence_, nullptr);
        if (pool) vkDestroyCommandPool(device, pool, nullptr);
        vkDestroyDevice(device, nullptr);
        device = VK_NULL_HANDLE;
    }
    if (messenger_) {
        auto destroyMessenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
        destroyMessenger(instance, messenger_, nullptr);
        messenger_ = VK_NULL_HANDLE;
    }
    if (instance) vkDestroyInstance(instance, nullptr);
    instance = VK_NULL_HANDLE;
}

rhi::VulkanDeviceImport RawVulkanHost::deviceImport() const {
    rhi::VulkanDeviceImport d;
    d.instance = instance;
    d.physicalDevice = physicalDevice;
    d.device = device;
    d.queue = queue;
    d.queueFamily = queueFamily;
    d.apiVersion = VK_API_VERSION_1_3;
    d.enabledExtensions = extensions_;
    d.enabledInstanceExtensions = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME};
    d.enabledFeatures = &features_;
    d.getInstanceProcAddr = vkGetInstanceProcAddr;
    d.debugName = "raw test host";
    return d;
}

uint32_t RawVulkanHost::memoryType(uint32_t typeBits, VkMemoryPropertyFlags properties) const {
    VkPhysicalDeviceMemoryProperties memory;
    vkGetPhysicalDeviceMemoryProperties(physicalDevice, &memory);
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & properties) == properties) return i;
    return 0;
}

RawImage RawVulkanHost::createImage(uint32_t width, uint32_t height, VkFormat format, VkImageUsageFlags usage) {
    RawImage out;
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {width, height, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    if (vkCreateImage(device, &info, nullptr, &out.image) != VK_SUCCESS) return out;
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device, out.image, &req);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    vkAllocateMemory(device, &alloc, nullptr, &out.memory);
    vkBindImageMemory(device, out.image, out.memory, 0);
    return out;
}

RawBuffer RawVulkanHost::createHostBuffer(VkDeviceSize bytes, VkBufferUsageFlags usage) {
    RawBuffer out;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = bytes;
    info.usage = usage;
    if (vkCreateBuffer(device, &info, nullptr, &out.buffer) != VK_SUCCESS) return out;
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device, out.buffer, &req);
    VkMemoryAllocateFlagsInfo flags{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO};
    flags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.pNext = (usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT) ? &flags : nullptr;
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex =
        memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    vkAllocateMemory(device, &alloc, nullptr, &out.memory);
    vkBindBufferMemory(device, out.buffer, out.memory, 0);
    vkMapMemory(device, out.memory, 0, VK_WHOLE_SIZE, 0, &out.mapped);
    return out;
}

void RawVulkanHost::destroy(RawImage& image) {
    vkDestroyImage(device, image.image, nullptr);
    vkFreeMemory(device, image.memory, nullptr);
    image = {};
}

void RawVulkanHost::destroy(RawBuffer& buffer) {
    vkDestroyBuffer(device, buffer.buffer, nullptr);
    vkFreeMemory(device, buffer.memory, nullptr);
    buffer = {};
}

void RawVulkanHost::begin() {
    vkResetCommandBuffer(commandBuffer, 0);
    VkCommandBufferBeginInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    info.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vkBeginCommandBuffer(commandBuffer, &info);
}

bool RawVulkanHost::endSubmitAndWait(const rhi::VulkanSubmitSignal* signal) {
    if (vkEndCommandBuffer(commandBuffer) != VK_SUCCESS) return false;
    VkCommandBufferSubmitInfo buffer{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    buffer.commandBuffer = commandBuffer;
    VkSemaphoreSubmitInfo signalInfo{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    submit.commandBufferInfoCount = 1;
    submit.pCommandBufferInfos = &buffer;
    if (signal) {
        signalInfo.semaphore = signal->semaphore;
        signalInfo.value = signal->value;
        signalInfo.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
        submit.signalSemaphoreInfoCount = 1;
        submit.pSignalSemaphoreInfos = &signalInfo;
    }
    vkResetFences(device, 1, &fence_);
    if (vkQueueSubmit2(queue, 1, &submit, fence_) != VK_SUCCESS) return false;
    return vkWaitForFences(device, 1, &fence_, VK_TRUE, UINT64_MAX) == VK_SUCCESS;
}

void RawVulkanHost::imageBarrier(VkImage image, VkImageLayout oldLayout, VkImageLayout newLayout,
                                 VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                                 VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
    VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    b.srcStageMask = srcStage;
    b.srcAccessMask = srcAccess;
    b.dstStageMask = dstStage;
    b.dstAccessMask = dstAccess;
    b.oldLayout = oldLayout;
    b.newLayout = newLayout;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.imageMemoryBarrierCount = 1;
    dep.pImageMemoryBarriers = &b;
    vkCmdPipelineBarrier2(commandBuffer, &dep);
}

void RawVulkanHost::memoryBarrier(VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                                  VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
    const VkMemoryBarrier2 b{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2, nullptr, srcStage, srcAccess, dstStage, dstAccess};
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.memoryBarrierCount = 1;
    dep.pMemoryBarriers = &b;
    vkCmdPipelineBarrier2(commandBuffer, &dep);
}

std::vector<std::string> RawVulkanHost::messages() {
    std::lock_guard lock(mutex_);
    return messages_;
}

}  // namespace caustics::test
