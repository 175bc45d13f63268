#include "host_gbuffer_compute.h"

#include <cstring>
#include <vector>

#include <glm/gtc/matrix_inverse.hpp>

#include "gpu_test.h"

namespace caustics::test {
namespace {

// std430 twins of host_gbuffer.comp's Triangle and InstanceLook.
struct TriangleGpu {
    glm::vec4 p[3];
    glm::vec4 n[3];
};
struct InstanceLookGpu {
    glm::vec4 albedoMetallic;
    glm::vec4 optics;
    glm::vec4 roughness;
};
struct CameraPush {
    glm::mat4 invViewProj;
    glm::vec4 eye;
    glm::vec4 forward;
    glm::vec4 size;
};

// gbuffer.h's optics encoding of a material.
glm::vec4 opticsOf(const scene::Material& m) {
    const float f0 = ((m.ior - 1.0f) / (m.ior + 1.0f)) * ((m.ior - 1.0f) / (m.ior + 1.0f));
    return {m.metallic + (1.0f - m.metallic) * m.specular * f0, (1.0f - m.metallic) * m.transmission, m.ior,
            m.isSpecular() ? 1.0f : 0.0f};
}

}  // namespace

bool HostGBufferCompute::create(RawVulkanHost& host, const scene::Scene& scene, uint32_t width, uint32_t height) {
    host_ = &host;
    width_ = width;
    height_ = height;
    std::vector<TriangleGpu> triangles;
    std::vector<InstanceLookGpu> looks;
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        const scene::Instance& instance = scene.instances[i];
        const scene::Mesh& mesh = scene.meshes[instance.mesh];
        const scene::Material& m = scene.materials[mesh.material];
        looks.push_back({glm::vec4(m.baseColor, m.metallic), opticsOf(m), glm::vec4(m.roughness)});
        const glm::mat3 normalMatrix = glm::inverseTranspose(glm::mat3(instance.transform));
        for (size_t k = 0; k + 2 < mesh.indices.size(); k += 3) {
            TriangleGpu t;
            for (int v = 0; v < 3; ++v) {
                const uint32_t index = mesh.indices[k + v];
                t.p[v] = glm::vec4(glm::vec3(instance.transform * glm::vec4(mesh.positions[index], 1.0f)), 0.0f);
                t.n[v] = glm::vec4(mesh.normals.empty() ? glm::vec3(0.0f) : normalMatrix * mesh.normals[index], 0.0f);
            }
            t.p[0].w = float(i);
            triangles.push_back(t);
        }
    }
    triangleCount_ = uint32_t(triangles.size());
    triangles_ = host.createHostBuffer(triangles.size() * sizeof(TriangleGpu), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    instances_ = host.createHostBuffer(looks.size() * sizeof(InstanceLookGpu), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    if (!triangles_.mapped || !instances_.mapped) return false;
    std::memcpy(triangles_.mapped, triangles.data(), triangles.size() * sizeof(TriangleGpu));
    std::memcpy(instances_.mapped, looks.data(), looks.size() * sizeof(InstanceLookGpu));

    for (int c = 0; c < kChannelCount; ++c) {
        images[c] = host.createImage(width, height, kFormats[c], kUsage);
        VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        view.image = images[c].image;
        view.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view.format = kFormats[c];
        view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        if (!images[c].image || vkCreateImageView(host.device, &view, nullptr, &views_[c]) != VK_SUCCESS) return false;
    }

    std::array<VkDescriptorSetLayoutBinding, 2 + kChannelCount> bindings{};
    for (uint32_t b = 0; b < bindings.size(); ++b)
        bindings[b] = {b, b < 2 ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1,
                       VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
    VkDescriptorSetLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    layoutInfo.bindingCount = uint32_t(bindings.size());
    layoutInfo.pBindings = bindings.data();
    if (vkCreateDescriptorSetLayout(host.device, &layoutInfo, nullptr, &setLayout_) != VK_SUCCESS) return false;
    const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2},
                                          {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kChannelCount}};
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.maxSets = 1;
    poolInfo.poolSizeCount = 2;
    poolInfo.pPoolSizes = sizes;
    if (vkCreateDescriptorPool(host.device, &poolInfo, nullptr, &descriptorPool_) != VK_SUCCESS) return false;
    VkDescriptorSetAllocateInfo allocInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    allocInfo.descriptorPool = descriptorPool_;
    allocInfo.descriptorSetCount = 1;
    allocInfo.pSetLayouts = &setLayout_;
    if (vkAllocateDescriptorSets(host.device, &allocInfo, &set_) != VK_SUCCESS) return false;
    const VkDescriptorBufferInfo buffers[] = {{triangles_.buffer, 0, VK_WHOLE_SIZE}, {instances_.buffer, 0, VK_WHOLE_SIZE}};
    std::array<VkDescriptorImageInfo, kChannelCount> imageInfos{};
    std::array<VkWriteDescriptorSet, 2 + kChannelCount> writes{};
    for (uint32_t b = 0; b < writes.size(); ++b) {
        writes[b] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[b].dstSet = set_;
        writes[b].dstBinding = b;
        writes[b].descriptorCount = 1;
        writes[b].descriptorType = bindings[b].descriptorType;
        if (b < 2) {
            writes[b].pBufferInfo = &buffers[b];
        } else {
            imageInfos[b - 2] = {VK_NULL_HANDLE, views_[b - 2], VK_IMAGE_LAYOUT_GENERAL};
            writes[b].pImageInfo = &imageInfos[b - 2];
        }
    }
    vkUpdateDescriptorSets(host.device, uint32_t(writes.size()), writes.data(), 0, nullptr);

    const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(CameraPush)};
    VkPipelineLayoutCreateInfo pipelineLayoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    pipelineLayoutInfo.setLayoutCount = 1;
    pipelineLayoutInfo.pSetLayouts = &setLayout_;
    pipelineLayoutInfo.pushConstantRangeCount = 1;
    pipelineLayoutInfo.pPushConstantRanges = &push;
    if (vkCreatePipelineLayout(host.device, &pipelineLayoutInfo, nullptr, &pipelineLayout_) != VK_SUCCESS) return false;
    const std::span<const uint32_t> code = test_shaders::spirv("embedding/host_gbuffer.comp");
    if (code.empty()) return false;
    VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    moduleInfo.codeSize = code.size_bytes();
    moduleInfo.pCode = code.data();
    VkShaderModule shader = VK_NULL_HANDLE;
    if (vkCreateShaderModule(host.device, &moduleInfo, nullptr, &shader) != VK_SUCCESS) return false;
    VkComputePipelineCreateInfo pipelineInfo{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    pipelineInfo.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    pipelineInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pipelineInfo.stage.module = shader;
    pipelineInfo.stage.pName = "main";
    pipelineInfo.layout = pipelineLayout_;
    const VkResult made = vkCreateComputePipelines(host.device, VK_NULL_HANDLE, 1, &pipelineInfo, nullptr, &pipeline_);
    vkDestroyShaderModule(host.device, shader, nullptr);
    return made == VK_SUCCESS;
}

void HostGBufferCompute::record(const CameraView& camera) {
    VkCommandBuffer cmd = host_->commandBuffer;
    for (const RawImage& image : images)
        host_->imageBarrier(image.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_NONE, 0,
                            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    const glm::mat4 invView = glm::inverse(camera.view);
    CameraPush push;
    push.invViewProj = glm::inverse(camera.proj * camera.view);
    push.eye = glm::vec4(glm::vec3(invView[3]), float(triangleCount_));
    // The view looks down -Z: the camera axis is minus the view's third basis vector in world space.
    push.forward = glm::vec4(glm::normalize(-glm::vec3(invView[2])), 0.0f);
    push.size = glm::vec4(float(width_), float(height_), float(idBase), float(idStride));   // exact below 2^24
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelineLayout_, 0, 1, &set_, 0, nullptr);
    vkCmdPushConstants(cmd, pipelineLayout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
    vkCmdDispatch(cmd, (width_ + 7) / 8, (height_ + 7) / 8, 1);
    // The module samples them in any shader stage.
    for (const RawImage& image : images)
        host_->imageBarrier(image.image, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                            VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

void HostGBufferCompute::destroy() {
    if (!host_) return;
    VkDevice device = host_->device;
    vkDeviceWaitIdle(device);
    vkDestroyPipeline(device, pipeline_, nullptr);
    vkDestroyPipelineLayout(device, pipelineLayout_, nullptr);
    vkDestroyDescriptorPool(device, descriptorPool_, nullptr);
    vkDestroyDescriptorSetLayout(device, setLayout_, nullptr);
    for (int c = 0; c < kChannelCount; ++c) {
        vkDestroyImageView(device, views_[c], nullptr);
        host_->destroy(images[c]);
    }
    host_->destroy(triangles_);
    host_->destroy(instances_);
    host_ = nullptr;
}

}  // namespace caustics::test
