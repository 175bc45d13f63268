// Imports of a host engine's images, buffers and acceleration structures (vulkan_interop.h). The RHI
// objects wrap the native handles without owning them; a use the native object cannot take (usage
// flag missing, format without the feature on this device) is refused naming the object.
#include <string>
#include <vector>

#include "caustics/rhi/vulkan_interop.h"
#include "vk_accel_struct.h"
#include "vk_buffer.h"
#include "vk_device.h"
#include "vk_texture.h"

namespace caustics::rhi {
namespace {

Result<vulkan::VulkanDevice*> vulkanDevice(IDevice& device, const char* call, const std::string& name) {
    if (device.backend() != Backend::Vulkan)
        return makeError(std::string(call) + " '" + name + "': the device is not a Vulkan device");
    return static_cast<vulkan::VulkanDevice*>(&device);
}

std::optional<Format> formatFromVk(VkFormat format) {
    for (uint32_t f = uint32_t(Format::R8_UNORM); f <= uint32_t(kLastFormat); ++f)
        if (Format(f) != Format::RGB32_FLOAT && vulkan::toVkFormat(Format(f)) == format) return Format(f);
    return std::nullopt;
}

std::string joined(const std::vector<std::string>& parts) {
    std::string out;
    for (const std::string& p : parts) out += (out.empty() ? "" : "; ") + p;
    return out;
}

struct TextureUseRule {
    TextureUsage use;
    const char* useName;
    VkImageUsageFlags usageBit;
    const char* usageName;
    VkFormatFeatureFlags formatFeature;
    const char* featureName;
};
const TextureUseRule kTextureRules[] = {
    {TextureUsage::Sampled, "Sampled", VK_IMAGE_USAGE_SAMPLED_BIT, "VK_IMAGE_USAGE_SAMPLED_BIT",
     VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT, "sampled-image"},
    {TextureUsage::Storage, "Storage", VK_IMAGE_USAGE_STORAGE_BIT, "VK_IMAGE_USAGE_STORAGE_BIT",
     VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT, "storage-image"},
    {TextureUsage::RenderTarget, "RenderTarget", VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT,
     "VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT", VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT, "color-attachment"},
    {TextureUsage::DepthStencil, "DepthStencil", VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
     "VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT", VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT,
     "depth-stencil-attachment"},
    {TextureUsage::CopySource, "CopySource", VK_IMAGE_USAGE_TRANSFER_SRC_BIT, "VK_IMAGE_USAGE_TRANSFER_SRC_BIT",
     VK_FORMAT_FEATURE_TRANSFER_SRC_BIT, "transfer-source"},
    {TextureUsage::CopyDest, "CopyDest", VK_IMAGE_USAGE_TRANSFER_DST_BIT, "VK_IMAGE_USAGE_TRANSFER_DST_BIT",
     VK_FORMAT_FEATURE_TRANSFER_DST_BIT, "transfer-destination"},
};

struct BufferUseRule {
    BufferUsage use;
    const char* useName;
    VkBufferUsageFlags usageBit;
    const char* usageName;
};
const BufferUseRule kBufferRules[] = {
    {BufferUsage::Vertex, "Vertex", VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, "VK_BUFFER_USAGE_VERTEX_BUFFER_BIT"},
    {BufferUsage::Index, "Index", VK_BUFFER_USAGE_INDEX_BUFFER_BIT, "VK_BUFFER_USAGE_INDEX_BUFFER_BIT"},
    {BufferUsage::Constant, "Constant", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, "VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT"},
    {BufferUsage::Storage, "Storage", VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "VK_BUFFER_USAGE_STORAGE_BUFFER_BIT"},
    {BufferUsage::Indirect, "Indirect", VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, "VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT"},
    {BufferUsage::AccelStructInput, "AccelStructInput", VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR,
     "VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR"},
    {BufferUsage::AccelStructStorage, "AccelStructStorage", VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR,
     "VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR"},
    {BufferUsage::ShaderTable, "ShaderTable", VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR,
     "VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR"},
    {BufferUsage::CopySource, "CopySource", VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "VK_BUFFER_USAGE_TRANSFER_SRC_BIT"},
    {BufferUsage::CopyDest, "CopyDest", VK_BUFFER_USAGE_TRANSFER_DST_BIT, "VK_BUFFER_USAGE_TRANSFER_DST_BIT"},
};

}  // namespace

Result<TextureHandle> importVulkanTexture(IDevice& device, const VulkanTextureImport& desc) {
    CAUSTICS_TRY(vulkan::VulkanDevice* vk, vulkanDevice(device, "importVulkanTexture", desc.debugName));
    const std::string what = "vulkan: cannot import texture '" + desc.debugName + "'";
    if (desc.image == VK_NULL_HANDLE) return makeError(what + ": image is VK_NULL_HANDLE");
    if (desc.width == 0 || desc.height == 0 || desc.arrayLayers == 0 || desc.mipLevels == 0)
        return makeError(what + ": width, height, arrayLayers and mipLevels must be non-zero");
    if (desc.cube && desc.arrayLayers % 6 != 0)
        return makeError(what + ": a cube needs a multiple of 6 layers, got " + std::to_string(desc.arrayLayers));
    std::optional<Format> format = formatFromVk(desc.format);
    if (!format) return makeError(what + ": VkFormat " + std::to_string(int(desc.format)) + " has no RHI format");

    VkFormatProperties formatProps{};
    vk->context().fn.vkGetPhysicalDeviceFormatProperties(vk->context().physicalDevice, desc.format, &formatProps);
    std::vector<std::string> problems;
    for (const TextureUseRule& rule : kTextureRules) {
        if (!hasAny(desc.uses, rule.use)) continue;
        if (!(desc.usage & rule.usageBit))
            problems.push_back(std::string("use ") + rule.useName + " needs " + rule.usageName +
                               ", which the image was not created with");
        if (!(formatProps.optimalTilingFeatures & rule.formatFeature))
            problems.push_back(std::string("use ") + rule.useName + ": format " + formatInfo(*format).name +
                               " has no " + rule.featureName + " support on this device");
    }
    if (!problems.empty()) return makeError(what + ": " + joined(problems));

    TextureDesc td;
    td.dimension = desc.cube ? TextureDimension::TextureCube
                 : desc.arrayLayers > 1 ? TextureDimension::Texture2DArray : TextureDimension::Texture2D;
    td.width = desc.width;
    td.height = desc.height;
    td.arrayLayers = desc.arrayLayers;
    td.mipLevels = desc.mipLevels;
    td.format = *format;
    td.usage = desc.uses;
    td.debugName = desc.debugName;
    return TextureHandle(vulkan::VulkanTexture::wrap(vk->contextPtr(), td, desc.image, desc.format));
}

Result<BufferHandle> importVulkanBuffer(IDevice& device, const VulkanBufferImport& desc) {
    CAUSTICS_TRY(vulkan::VulkanDevice* vk, vulkanDevice(device, "importVulkanBuffer", desc.debugName));
    const std::string what = "vulkan: cannot import buffer '" + desc.debugName + "'";
    if (desc.buffer == VK_NULL_HANDLE) return makeError(what + ": buffer is VK_NULL_HANDLE");
    if (desc.byteSize == 0) return makeError(what + ": byteSize is 0");
    std::vector<std::string> problems;
    for (const BufferUseRule& rule : kBufferRules)
        if (hasAny(desc.uses, rule.use) && !(desc.usage & rule.usageBit))
            problems.push_back(std::string("use ") + rule.useName + " needs " + rule.usageName +
                               ", which the buffer was not created with");
    const bool hasAddress = desc.usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
    // Builds and trace calls take these buffers by device address (VK_KHR_acceleration_structure).
    if (hasAny(desc.uses, BufferUsage::AccelStructInput | BufferUsage::AccelStructStorage | BufferUsage::ShaderTable) &&
        !hasAddress && desc.deviceAddress == 0)
        problems.push_back("acceleration-structure and shader-table uses need VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT");
    if (!problems.empty()) return makeError(what + ": " + joined(problems));

    uint64_t address = desc.deviceAddress;
    if (address == 0 && hasAddress) {
        VkBufferDeviceAddressInfo info{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
        info.buffer = desc.buffer;
        address = vk->context().fn.vkGetBufferDeviceAddress(vk->context().device, &info);
    }
    BufferDesc bd;
    bd.byteSize = desc.byteSize;
    bd.usage = desc.uses;
    bd.memory = MemoryType::DeviceLocal;
    bd.structStride = desc.structStride;
    bd.debugName = desc.debugName;
    return BufferHandle(vulkan::VulkanBuffer::wrap(vk->contextPtr(), bd, desc.buffer, address));
}

Result<AccelStructHandle> importVulkanAccelStruct(IDevice& device, const VulkanAccelStructImport& desc) {
    CAUSTICS_TRY(vulkan::VulkanDevice* vk, vulkanDevice(device, "importVulkanAccelStruct", desc.debugName));
    const std::string what = "vulkan: cannot import acceleration structure '" + desc.debugName + "'";
    if (desc.accelStruct == VK_NULL_HANDLE) return makeError(what + ": accelStruct is VK_NULL_HANDLE");
    const vulkan::VulkanContext& ctx = vk->context();
    if (!ctx.fn.vkGetAccelerationStructureDeviceAddressKHR)
        return makeError(what + ": the device has no VK_KHR_acceleration_structure enabled");
    uint64_t address = desc.deviceAddress;
    if (address == 0) {
        VkAccelerationStructureDeviceAddressInfoKHR info{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR};
        info.accelerationStructure = desc.accelStruct;
        address = ctx.fn.vkGetAccelerationStructureDeviceAddressKHR(ctx.device, &info);
    }
    AccelStructDesc ad;
    ad.isTopLevel = desc.isTopLevel;
    ad.debugName = desc.debugName;
    return AccelStructHandle(vulkan::VulkanAccelStruct::wrap(vk->contextPtr(), ad, desc.accelStruct, address));
}

Result<ResourceState> resourceStateFromVkImageLayout(VkImageLayout layout, bool isDepthFormat) {
    switch (layout) {
        case VK_IMAGE_LAYOUT_UNDEFINED: return ResourceState::Undefined;
        case VK_IMAGE_LAYOUT_GENERAL: return ResourceState::Common;   // waits for and on all commands
        case VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL: return ResourceState::RenderTarget;
        case VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL: return ResourceState::DepthWrite;
        case VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL:
            if (isDepthFormat) return ResourceState::ShaderResource | ResourceState::DepthRead;
            return ResourceState::DepthRead;
        case VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL: return ResourceState::CopySource;
        case VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL: return ResourceState::CopyDest;
        case VK_IMAGE_LAYOUT_PRESENT_SRC_KHR: return ResourceState::Present;
        case VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL:
            if (!isDepthFormat) return ResourceState::ShaderResource;
            return makeError("vulkan: a depth image in VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL has no RHI state; "
                             "the RHI reads depth in VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL");
        default:
            return makeError("vulkan: VkImageLayout " + std::to_string(int(layout)) +
                             " has no RHI state; use UNDEFINED, GENERAL, SHADER_READ_ONLY_OPTIMAL, "
                             "COLOR_ATTACHMENT_OPTIMAL, DEPTH_STENCIL_ATTACHMENT_OPTIMAL, "
                             "DEPTH_STENCIL_READ_ONLY_OPTIMAL, TRANSFER_SRC_OPTIMAL, TRANSFER_DST_OPTIMAL or PRESENT_SRC_KHR");
    }
}

}  // namespace caustics::rhi
