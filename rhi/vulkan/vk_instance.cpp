#include "vk_instance.h"

#include <cstring>
#include <string>
#include <vector>

namespace caustics::rhi::vulkan {
namespace {

VKAPI_ATTR VkBool32 VKAPI_CALL debugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                             VkDebugUtilsMessageTypeFlagsEXT,
                                             const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    auto* context = static_cast<VulkanContext*>(user);
    LogLevel level = LogLevel::Debug;
    if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) level = LogLevel::Error;
    else if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) level = LogLevel::Warning;
    // INFO messages are the loader's and layers' status lines: Debug, so the default sink
    // stays quiet; a host callback still sees them.
    std::string message = "vulkan validation: ";
    if (data->pMessageIdName) message += std::string(data->pMessageIdName) + ": ";
    if (data->pMessage) message += data->pMessage;
    if (context && context->validationCallback) context->validationCallback(level, message);
    else log(level, message);
    return VK_FALSE;   // never abort the call (spec: applications should return VK_FALSE)
}

bool hasLayer(const char* name) {
    uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    for (const auto& l : layers)
        if (std::strcmp(l.layerName, name) == 0) return true;
    return false;
}

bool hasInstanceExtension(const char* layer, const char* name) {
    uint32_t count = 0;
    vkEnumerateInstanceExtensionProperties(layer, &count, nullptr);
    std::vector<VkExtensionProperties> exts(count);
    vkEnumerateInstanceExtensionProperties(layer, &count, exts.data());
    for (const auto& e : exts)
        if (std::strcmp(e.extensionName, name) == 0) return true;
    return false;
}

}  // namespace

Status createInstance(VulkanContext& context, const DeviceDesc& desc) {
    constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
    std::vector<const char*> layers;
    std::vector<const char*> extensions;
    if (desc.enableValidation) {
        if (!hasLayer(kValidationLayer))
            return makeError("vulkan: enableValidation needs VK_LAYER_KHRONOS_validation (Debian: vulkan-validationlayers)");
        layers.push_back(kValidationLayer);
    }
    const bool debugUtils = hasInstanceExtension(nullptr, VK_EXT_DEBUG_UTILS_EXTENSION_NAME) ||
                            (desc.enableValidation && hasInstanceExtension(kValidationLayer, VK_EXT_DEBUG_UTILS_EXTENSION_NAME));
    if (debugUtils) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    const bool validationFeatures =
        desc.enableValidation && hasInstanceExtension(kValidationLayer, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
    if (validationFeatures) extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "caustics";
    app.pEngineName = "caustics";
    app.apiVersion = VK_API_VERSION_1_3;

    VkDebugUtilsMessengerCreateInfoEXT messenger{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messenger.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_INFO_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messenger.pfnUserCallback = debugCallback;
    messenger.pUserData = &context;

    // Synchronization validation is off by default in the layer; turn it on (VK_EXT_validation_features).
    const VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = enables;

    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    info.enabledLayerCount = uint32_t(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    // Chain the messenger so instance creation/destruction messages are reported too.
    const void* chain = nullptr;
    if (debugUtils) {
        messenger.pNext = chain;
        chain = &messenger;
    }
    if (validationFeatures) {
        features.pNext = chain;
        chain = &features;
    }
    info.pNext = chain;
    VkResult r = vkCreateInstance(&info, nullptr, &context.instance);
    if (r != VK_SUCCESS) return vkError(r, "vkCreateInstance (Vulkan 1.3)");

    // Every later call goes through context.fn, loaded through the loader's vkGetInstanceProcAddr.
    CAUSTICS_CHECK(loadInstanceDispatch(context.fn, vkGetInstanceProcAddr, context.instance, debugUtils, "our instance"));
    if (debugUtils) {
        messenger.pNext = nullptr;
        if (context.fn.vkCreateDebugUtilsMessengerEXT)
            context.fn.vkCreateDebugUtilsMessengerEXT(context.instance, &messenger, nullptr, &context.messenger);
    }
    return okStatus();
}

}  // namespace caustics::rhi::vulkan
