// Graphics pipelines for dynamic rendering (VK_KHR_dynamic_rendering, core 1.3).
#include <string>

#include "vk_pipeline.h"
#include "vk_texture.h"

namespace caustics::rhi::vulkan {
namespace {

VkCompareOp toVkCompare(CompareOp op) {
    switch (op) {
        case CompareOp::Never: return VK_COMPARE_OP_NEVER;
        case CompareOp::Less: return VK_COMPARE_OP_LESS;
        case CompareOp::LessOrEqual: return VK_COMPARE_OP_LESS_OR_EQUAL;
        case CompareOp::Equal: return VK_COMPARE_OP_EQUAL;
        case CompareOp::Greater: return VK_COMPARE_OP_GREATER;
        case CompareOp::GreaterOrEqual: return VK_COMPARE_OP_GREATER_OR_EQUAL;
        case CompareOp::Always: return VK_COMPARE_OP_ALWAYS;
    }
    return VK_COMPARE_OP_ALWAYS;
}

VkPrimitiveTopology toVkTopology(PrimitiveTopology t) {
    switch (t) {
        case PrimitiveTopology::TriangleList: return VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
        case PrimitiveTopology::TriangleStrip: return VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP;
        case PrimitiveTopology::LineList: return VK_PRIMITIVE_TOPOLOGY_LINE_LIST;
        case PrimitiveTopology::PointList: return VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
    }
    return VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
}

}  // namespace

Result<std::shared_ptr<VulkanGraphicsPipeline>> VulkanGraphicsPipeline::create(const ContextPtr& context,
                                                                               const GraphicsPipelineDesc& desc) {
    const VulkanContext& ctx = *context;
    std::shared_ptr<VulkanGraphicsPipeline> pipeline(new VulkanGraphicsPipeline(desc));
    pipeline->context_ = context;
    pipeline->bindPoint_ = VK_PIPELINE_BIND_POINT_GRAPHICS;
    auto layout = createPipelineLayout(ctx, desc.bindings, desc.debugName);
    if (!layout) return layout.error();
    pipeline->layout_ = layout.value();

    std::vector<VkPipelineShaderStageCreateInfo> stages;
    std::vector<VkShaderModule> modules;
    auto addStage = [&](const ShaderEntry& entry, VkShaderStageFlagBits stage) -> Status {
        auto module = createShaderModule(ctx, entry.code);
        if (!module) return module.error();
        modules.push_back(module.value());
        VkPipelineShaderStageCreateInfo s{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
        s.stage = stage;
        s.module = module.value();
        s.pName = entry.entryPoint.c_str();
        stages.push_back(s);
        return okStatus();
    };
    auto destroyModules = [&] {
        for (VkShaderModule m : modules) ctx.fn.vkDestroyShaderModule(ctx.device, m, nullptr);
    };
    Status vs = addStage(desc.vertexShader, VK_SHADER_STAGE_VERTEX_BIT);
    Status fs = desc.fragmentShader.stage != ShaderStage::None && !desc.fragmentShader.code.bytes.empty()
                    ? addStage(desc.fragmentShader, VK_SHADER_STAGE_FRAGMENT_BIT)
                    : okStatus();
    if (!vs || !fs) {
        destroyModules();
        return !vs ? vs.error() : fs.error();
    }

    std::vector<VkVertexInputBindingDescription> vbindings;
    for (const VertexBufferLayout& b : desc.vertexBuffers)
        vbindings.push_back({b.binding, b.stride, VK_VERTEX_INPUT_RATE_VERTEX});
    std::vector<VkVertexInputAttributeDescription> attributes;
    for (const VertexAttribute& a : desc.vertexAttributes)
        attributes.push_back({a.location, a.binding, toVkFormat(a.format), a.offset});
    VkPipelineVertexInputStateCreateInfo vertexInput{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vertexInput.vertexBindingDescriptionCount = uint32_t(vbindings.size());
    vertexInput.pVertexBindingDescriptions = vbindings.data();
    vertexInput.vertexAttributeDescriptionCount = uint32_t(attributes.size());
    vertexInput.pVertexAttributeDescriptions = attributes.data();

    VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    assembly.topology = toVkTopology(desc.topology);
    VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = desc.cullMode == CullMode::None    ? VK_CULL_MODE_NONE
                      : desc.cullMode == CullMode::Front ? VK_CULL_MODE_FRONT_BIT
                                                         : VK_CULL_MODE_BACK_BIT;
    raster.frontFace = desc.frontCounterClockwise ? VK_FRONT_FACE_COUNTER_CLOCKWISE : VK_FRONT_FACE_CLOCKWISE;
    raster.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    const bool hasDepth = desc.depthFormat != Format::Unknown;
    depth.depthTestEnable = hasDepth && desc.depthTest;
    depth.depthWriteEnable = hasDepth && desc.depthWrite;
    depth.depthCompareOp = toVkCompare(desc.depthCompare);

    std::vector<VkPipelineColorBlendAttachmentState> blends(desc.colorFormats.size());
    for (auto& b : blends) {
        b = {};
        b.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT |
                           VK_COLOR_COMPONENT_A_BIT;
        if (desc.additiveBlend) {   // dst = 1*src + 1*dst
            b.blendEnable = VK_TRUE;
            b.srcColorBlendFactor = b.dstColorBlendFactor = VK_BLEND_FACTOR_ONE;
            b.srcAlphaBlendFactor = b.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
            b.colorBlendOp = b.alphaBlendOp = VK_BLEND_OP_ADD;
        }
    }
    VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blend.attachmentCount = uint32_t(blends.size());
    blend.pAttachments = blends.data();

    const VkDynamicState dynamicStates[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dynamic.dynamicStateCount = 2;
    dynamic.pDynamicStates = dynamicStates;

    std::vector<VkFormat> colorFormats;
    for (Format f : desc.colorFormats) colorFormats.push_back(toVkFormat(f));
    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rendering.colorAttachmentCount = uint32_t(colorFormats.size());
    rendering.pColorAttachmentFormats = colorFormats.data();
    rendering.depthAttachmentFormat = hasDepth ? toVkFormat(desc.depthFormat) : VK_FORMAT_UNDEFINED;
    rendering.stencilAttachmentFormat =
        hasDepth && formatInfo(desc.depthFormat).hasStencil ? toVkFormat(desc.depthFormat) : VK_FORMAT_UNDEFINED;

    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    info.pNext = &rendering;
    info.stageCount = uint32_t(stages.size());
    info.pStages = stages.data();
    info.pVertexInputState = &vertexInput;
    info.pInputAssemblyState = &assembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depth;
    info.pColorBlendState = &blend;
    info.pDynamicState = &dynamic;
    info.layout = pipeline->layout_;
    VkResult r = ctx.fn.vkCreateGraphicsPipelines(ctx.device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline->pipeline_);
    destroyModules();
    if (r != VK_SUCCESS) return vkError(r, "vkCreateGraphicsPipelines", desc.debugName);
    ctx.setName(VK_OBJECT_TYPE_PIPELINE, pipeline->pipeline_, desc.debugName);
    return pipeline;
}

}  // namespace caustics::rhi::vulkan
