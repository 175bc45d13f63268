#include "vk_pipeline.h"

#include <string>

#include "vk_binding.h"

namespace caustics::rhi::vulkan {

Result<VkPipelineLayout> createPipelineLayout(const VulkanContext& context, const PipelineBindings& bindings,
                                              std::string_view debugName) {
    if (bindings.pushConstantBytes > context.properties.limits.maxPushConstantsSize)
        return makeError("vulkan: '" + std::string(debugName) + "' asks for " +
                         std::to_string(bindings.pushConstantBytes) + " push-constant bytes, the device allows " +
                         std::to_string(context.properties.limits.maxPushConstantsSize));
    std::vector<VkDescriptorSetLayout> sets;
    for (size_t i = 0; i < bindings.layouts.size(); ++i) {
        if (!bindings.layouts[i])
            return makeError("vulkan: '" + std::string(debugName) + "' binding layout " + std::to_string(i) +
                             " is null");
        sets.push_back(toVk(bindings.layouts[i])->handle());
    }
    VkPushConstantRange range{VK_SHADER_STAGE_ALL, 0, bindings.pushConstantBytes};
    VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    info.setLayoutCount = uint32_t(sets.size());
    info.pSetLayouts = sets.data();
    info.pushConstantRangeCount = bindings.pushConstantBytes > 0 ? 1 : 0;
    info.pPushConstantRanges = &range;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkResult r = context.fn.vkCreatePipelineLayout(context.device, &info, nullptr, &layout);
    if (r != VK_SUCCESS) return vkError(r, "vkCreatePipelineLayout", debugName);
    context.setName(VK_OBJECT_TYPE_PIPELINE_LAYOUT, layout, debugName);
    return layout;
}

Result<VkShaderModule> createShaderModule(const VulkanContext& context, const ShaderCode& code) {
    if (code.kind != ShaderCodeKind::SPIRV)
        return makeError("vulkan: shader '" + code.debugName + "' is not SPIR-V");
    if (code.bytes.empty() || code.bytes.size() % 4 != 0)
        return makeError("vulkan: shader '" + code.debugName + "' has no SPIR-V or a size not a multiple of 4");
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = code.bytes.size();
    info.pCode = reinterpret_cast<const uint32_t*>(code.bytes.data());
    VkShaderModule module = VK_NULL_HANDLE;
    VkResult r = context.fn.vkCreateShaderModule(context.device, &info, nullptr, &module);
    if (r != VK_SUCCESS) return vkError(r, "vkCreateShaderModule", code.debugName);
    context.setName(VK_OBJECT_TYPE_SHADER_MODULE, module, code.debugName);
    return module;
}

VkShaderStageFlagBits toVkShaderStage(ShaderStage stage) {
    return VkShaderStageFlagBits(toVkShaderStages(stage));
}

void VulkanPipelineBase::release() {
    if (!context_) return;
    ContextPtr ctx = context_;
    VkPipeline p = pipeline_;
    VkPipelineLayout l = layout_;
    ctx->deferDestroy([ctx, p, l] {
        if (p != VK_NULL_HANDLE) ctx->fn.vkDestroyPipeline(ctx->device, p, nullptr);
        if (l != VK_NULL_HANDLE) ctx->fn.vkDestroyPipelineLayout(ctx->device, l, nullptr);
    });
}

Result<std::shared_ptr<VulkanComputePipeline>> VulkanComputePipeline::create(const ContextPtr& context,
                                                                             const ComputePipelineDesc& desc) {
    std::shared_ptr<VulkanComputePipeline> pipeline(new VulkanComputePipeline(desc));
    pipeline->context_ = context;
    pipeline->bindPoint_ = VK_PIPELINE_BIND_POINT_COMPUTE;
    auto layout = createPipelineLayout(*context, desc.bindings, desc.debugName);
    if (!layout) return layout.error();
    pipeline->layout_ = layout.value();
    auto module = createShaderModule(*context, desc.shader.code);
    if (!module) return module.error();

    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module.value();
    info.stage.pName = desc.shader.entryPoint.c_str();
    info.layout = pipeline->layout_;
    VkResult r = context->fn.vkCreateComputePipelines(context->device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline->pipeline_);
    context->fn.vkDestroyShaderModule(context->device, module.value(), nullptr);
    if (r != VK_SUCCESS) return vkError(r, "vkCreateComputePipelines", desc.debugName);
    context->setName(VK_OBJECT_TYPE_PIPELINE, pipeline->pipeline_, desc.debugName);
    return pipeline;
}

}  // namespace caustics::rhi::vulkan
