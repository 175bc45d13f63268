#pragma once
// Shader binding table: records (group handle + local data, Vulkan shaderRecordEXT) laid out by
// rhi::computeShaderTableLayout with the device's handle size and alignments, in a device-local buffer
// with VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR; dispatchRays takes the four regions.
#include <vulkan/vulkan.h>

#include <functional>
#include <string>
#include <vector>

#include "caustics/rhi/shader_table_layout.h"
#include "caustics/rhi/state_object.h"
#include "vk_context.h"

namespace caustics::rhi::vulkan {

class VulkanDevice;

// The table's bytes on the host, device-free; errors name
// the record's export and the table.
struct ShaderTableImage {
    ShaderTableLayout layout;
    std::vector<uint8_t> bytes;
};
Result<ShaderTableImage> buildShaderTableImage(const ShaderTableDesc& desc, const ShaderTableAlignment& alignment,
                                               uint32_t localDataBytes,
                                               const std::function<const uint8_t*(const std::string&)>& handleOf);

class VulkanShaderTable final : public IShaderTable {
public:
    static Result<std::shared_ptr<VulkanShaderTable>> create(VulkanDevice& device, const ShaderTableDesc& desc);
    const ShaderTableDesc& desc() const override { return desc_; }

    const VkStridedDeviceAddressRegionKHR& rayGen() const { return regions_[0]; }
    const VkStridedDeviceAddressRegionKHR& miss() const { return regions_[1]; }
    const VkStridedDeviceAddressRegionKHR& hitGroup() const { return regions_[2]; }
    const VkStridedDeviceAddressRegionKHR& callable() const { return regions_[3]; }
    const ShaderTableLayout& layout() const { return layout_; }

private:
    explicit VulkanShaderTable(const ShaderTableDesc& desc) : desc_(desc) {}
    ShaderTableDesc desc_;
    ShaderTableLayout layout_;
    BufferHandle buffer_;
    VkStridedDeviceAddressRegionKHR regions_[4]{};
};

inline VulkanShaderTable* toVk(const ShaderTableHandle& t) { return static_cast<VulkanShaderTable*>(t.get()); }

}  // namespace caustics::rhi::vulkan
