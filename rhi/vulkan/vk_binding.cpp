#include "vk_binding.h"

#include <string>

#include "vk_buffer.h"
#include "vk_device.h"
#include "vk_texture.h"

namespace caustics::rhi::vulkan {

VkDescriptorType toVkDescriptorType(BindingType type) {
    switch (type) {
        case BindingType::ConstantBuffer: return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
        case BindingType::StorageBufferRO: return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        case BindingType::StorageBufferRW: return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        case BindingType::SampledTexture: return VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
        case BindingType::StorageTexture: return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
        case BindingType::Sampler: return VK_DESCRIPTOR_TYPE_SAMPLER;
        case BindingType::AccelStruct: return VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
    }
    return VK_DESCRIPTOR_TYPE_MAX_ENUM;
}

VkShaderStageFlags toVkShaderStages(ShaderStage stages) {
    VkShaderStageFlags f = 0;
    if (hasAny(stages, ShaderStage::Vertex)) f |= VK_SHADER_STAGE_VERTEX_BIT;
    if (hasAny(stages, ShaderStage::Fragment)) f |= VK_SHADER_STAGE_FRAGMENT_BIT;
    if (hasAny(stages, ShaderStage::Compute)) f |= VK_SHADER_STAGE_COMPUTE_BIT;
    if (hasAny(stages, ShaderStage::RayGen)) f |= VK_SHADER_STAGE_RAYGEN_BIT_KHR;
    if (hasAny(stages, ShaderStage::Miss)) f |= VK_SHADER_STAGE_MISS_BIT_KHR;
    if (hasAny(stages, ShaderStage::ClosestHit)) f |= VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR;
    if (hasAny(stages, ShaderStage::AnyHit)) f |= VK_SHADER_STAGE_ANY_HIT_BIT_KHR;
    if (hasAny(stages, ShaderStage::Intersection)) f |= VK_SHADER_STAGE_INTERSECTION_BIT_KHR;
    if (hasAny(stages, ShaderStage::Callable)) f |= VK_SHADER_STAGE_CALLABLE_BIT_KHR;
    return f;
}

// ---- DescriptorAllocator ----

DescriptorAllocator::~DescriptorAllocator() {
    for (VkDescriptorPool p : pools_) context_.fn.vkDestroyDescriptorPool(context_.device, p, nullptr);
}

Result<VkDescriptorPool> DescriptorAllocator::newPool() {
    // Generous fixed sizes; a full pool just leads to another one.
    std::vector<VkDescriptorPoolSize> sizes = {
        {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 2048}, {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 4096},
        {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, 8192},  {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 2048},
        {VK_DESCRIPTOR_TYPE_SAMPLER, 1024},
    };
    if (context_.capabilities.accelerationStructure)
        sizes.push_back({VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 512});
    VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    info.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    info.maxSets = 1024;
    info.poolSizeCount = uint32_t(sizes.size());
    info.pPoolSizes = sizes.data();
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkResult r = context_.fn.vkCreateDescriptorPool(context_.device, &info, nullptr, &pool);
    if (r != VK_SUCCESS) return vkError(r, "vkCreateDescriptorPool");
    pools_.push_back(pool);
    return pool;
}

Result<VkDescriptorSet> DescriptorAllocator::allocate(VkDescriptorSetLayout layout, VkDescriptorPool& poolOut) {
    std::lock_guard lock(mutex_);
    VkDescriptorSetAllocateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    info.descriptorSetCount = 1;
    info.pSetLayouts = &layout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    for (size_t i = pools_.size(); i-- > 0;) {
        info.descriptorPool = pools_[i];
        if (context_.fn.vkAllocateDescriptorSets(context_.device, &info, &set) == VK_SUCCESS) {
            poolOut = pools_[i];
            return set;
        }
    }
    auto pool = newPool();
    if (!pool) return pool.error();
    info.descriptorPool = pool.value();
    VkResult r = context_.fn.vkAllocateDescriptorSets(context_.device, &info, &set);
    if (r != VK_SUCCESS) return vkError(r, "vkAllocateDescriptorSets");
    poolOut = pool.value();
    return set;
}

void DescriptorAllocator::free(VkDescriptorPool pool, VkDescriptorSet set) {
    std::lock_guard lock(mutex_);
    context_.fn.vkFreeDescriptorSets(context_.device, pool, 1, &set);
}

// ---- VulkanBindingLayout ----

Result<std::shared_ptr<VulkanBindingLayout>> VulkanBindingLayout::create(const ContextPtr& context,
                                                                         const BindingLayoutDesc& desc) {
    std::shared_ptr<VulkanBindingLayout> layout(new VulkanBindingLayout(context, desc));
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    std::vector<VkDescriptorBindingFlags> flags;
    VkShaderStageFlags stages = toVkShaderStages(desc.visibility);
    if (!context->capabilities.rayTracingPipeline)
        stages &= ~VkShaderStageFlags(toVkShaderStages(ShaderStage::AllRayTracing));
    for (const BindingLayoutItem& item : desc.items) {
        if (item.type == BindingType::AccelStruct && !context->capabilities.accelerationStructure)
            return makeError("vulkan: binding layout uses an acceleration structure but the device has none");
        VkDescriptorSetLayoutBinding b{};
        b.binding = item.slot;
        b.descriptorType = toVkDescriptorType(item.type);
        b.descriptorCount = item.arraySize;
        b.stageFlags = stages;
        bindings.push_back(b);
        // Arrays (bindless textures) may hold unused elements in shaders that index dynamically.
        flags.push_back(item.arraySize > 1 ? VK_DESCRIPTOR_BINDING_PARTIALLY_BOUND_BIT : 0);
    }
    VkDescriptorSetLayoutBindingFlagsCreateInfo flagsInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_BINDING_FLAGS_CREATE_INFO};
    flagsInfo.bindingCount = uint32_t(flags.size());
    flagsInfo.pBindingFlags = flags.data();
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.pNext = &flagsInfo;
    info.bindingCount = uint32_t(bindings.size());
    info.pBindings = bindings.data();
    VkResult r = context->fn.vkCreateDescriptorSetLayout(context->device, &info, nullptr, &layout->layout_);
    if (r != VK_SUCCESS) return vkError(r, "vkCreateDescriptorSetLayout");
    return layout;
}

VulkanBindingLayout::~VulkanBindingLayout() {
    ContextPtr ctx = context_;
    VkDescriptorSetLayout l = layout_;
    ctx->deferDestroy([ctx, l] { ctx->fn.vkDestroyDescriptorSetLayout(ctx->device, l, nullptr); });
}

// ---- VulkanBindingSet ----

Result<std::shared_ptr<VulkanBindingSet>> VulkanBindingSet::create(const ContextPtr& context,
                                                                   const BindingSetDesc& desc,
                                                                   const BindingLayoutHandle& layout) {
    if (!layout) return makeError("vulkan: createBindingSet without a layout");
    std::shared_ptr<VulkanBindingSet> set(new VulkanBindingSet(context, desc, layout));
    auto allocated = context->descriptors->allocate(toVk(layout)->handle(), set->pool_);
    if (!allocated) return allocated.error();
    set->set_ = allocated.value();

    const size_t n = desc.items.size();
    std::vector<VkWriteDescriptorSet> writes(n);
    std::vector<VkDescriptorBufferInfo> bufferInfos(n);
    std::vector<VkDescriptorImageInfo> imageInfos(n);
    std::vector<VkWriteDescriptorSetAccelerationStructureKHR> asInfos(n);
    std::vector<VkAccelerationStructureKHR> asHandles(n);
    for (size_t i = 0; i < n; ++i) {
        const BindingSetItem& item = desc.items[i];
        VkWriteDescriptorSet& w = writes[i];
        w = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        w.dstSet = set->set_;
        w.dstBinding = item.slot;
        w.dstArrayElement = item.arrayElement;
        w.descriptorCount = 1;
        w.descriptorType = toVkDescriptorType(item.type);
        const std::string where = "binding set item slot " + std::to_string(item.slot);
        switch (item.type) {
            case BindingType::ConstantBuffer:
            case BindingType::StorageBufferRO:
            case BindingType::StorageBufferRW:
                if (!item.buffer) return makeError("vulkan: " + where + " has no buffer");
                bufferInfos[i] = {toVk(item.buffer)->handle(), item.offset, item.range ? item.range : VK_WHOLE_SIZE};
                w.pBufferInfo = &bufferInfos[i];
                break;
            case BindingType::SampledTexture:
                if (!item.texture) return makeError("vulkan: " + where + " has no texture");
                imageInfos[i] = {VK_NULL_HANDLE, toVk(item.texture)->sampledView(),
                                 formatInfo(item.texture->desc().format).isDepth
                                     ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL
                                     : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
                w.pImageInfo = &imageInfos[i];
                break;
            case BindingType::StorageTexture:
                if (!item.texture) return makeError("vulkan: " + where + " has no texture");
                imageInfos[i] = {VK_NULL_HANDLE, toVk(item.texture)->storageView(), VK_IMAGE_LAYOUT_GENERAL};
                w.pImageInfo = &imageInfos[i];
                break;
            case BindingType::Sampler:
                if (!item.sampler) return makeError("vulkan: " + where + " has no sampler");
                imageInfos[i] = {toVk(item.sampler)->handle(), VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED};
                w.pImageInfo = &imageInfos[i];
                break;
            case BindingType::AccelStruct:
                if (!item.accelStruct) return makeError("vulkan: " + where + " has no acceleration structure");
                asHandles[i] = vulkanAccelStructHandle(*item.accelStruct);
                asInfos[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR};
                asInfos[i].accelerationStructureCount = 1;
                asInfos[i].pAccelerationStructures = &asHandles[i];
                w.pNext = &asInfos[i];
                break;
        }
    }
    context->fn.vkUpdateDescriptorSets(context->device, uint32_t(writes.size()), writes.data(), 0, nullptr);
    return set;
}

VulkanBindingSet::~VulkanBindingSet() {
    if (set_ == VK_NULL_HANDLE) return;
    ContextPtr ctx = context_;
    VkDescriptorPool pool = pool_;
    VkDescriptorSet set = set_;
    ctx->deferDestroy([ctx, pool, set] { ctx->descriptors->free(pool, set); });
}

}  // namespace caustics::rhi::vulkan
