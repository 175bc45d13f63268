#pragma once
// The plain-Vulkan host engine's G-buffer pass (host_engine_test.cpp): its own images, buffers,
// descriptor set and compute pipeline (tests/gpu/shaders/embedding/host_gbuffer.comp), created and
// recorded with raw Vulkan calls on a RawVulkanHost. It writes the module's G-buffer contract
// (passes/include/caustics/gbuffer.h) and leaves the images in SHADER_READ_ONLY_OPTIMAL.
#include <vulkan/vulkan.h>

#include <array>

#include "caustics/camera_view.h"
#include "caustics/scene/scene.h"
#include "raw_vulkan_host.h"

namespace caustics::test {

class HostGBufferCompute {
public:
    enum Channel { NormalRoughness, AlbedoMetallic, Optics, LinearDepth, ObjectId, kChannelCount };
    static constexpr std::array<VkFormat, kChannelCount> kFormats = {
        VK_FORMAT_R16G16B16A16_SFLOAT, VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_R16G16B16A16_SFLOAT,
        VK_FORMAT_R32_SFLOAT, VK_FORMAT_R32_UINT};
    // TRANSFER_SRC: the test reads objectId and linearDepth back to compare them with the module's pass.
    static constexpr VkImageUsageFlags kUsage =
        VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;

    // Uploads the scene's triangles in world space and its instances' materials; false on failure.
    bool create(RawVulkanHost& host, const scene::Scene& scene, uint32_t width, uint32_t height);
    // Records into host.commandBuffer: UNDEFINED -> GENERAL, the dispatch, GENERAL -> SHADER_READ_ONLY.
    void record(const CameraView& camera);
    void destroy();

    std::array<RawImage, kChannelCount> images{};
    // The host's object id of instance row k is idBase + idStride * k (1 + k: the module's own ids).
    uint32_t idBase = 1, idStride = 1;

private:
    RawVulkanHost* host_ = nullptr;
    uint32_t width_ = 0, height_ = 0, triangleCount_ = 0;
    RawBuffer triangles_{}, instances_{};
    std::array<VkImageView, kChannelCount> views_{};
    VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
    VkDescriptorPool descriptorPool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    VkPipelineLayout pipelineLayout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

}  // namespace caustics::test
