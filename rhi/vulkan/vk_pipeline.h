#pragma once
// Compute and graphics pipelines, plus the pieces the ray-tracing state object reuses: the pipeline
// layout built from PipelineBindings and shader-module creation.
#include <vulkan/vulkan.h>

#include "caustics/rhi/pipeline.h"
#include "vk_context.h"

namespace caustics::rhi::vulkan {

// Push constants are one range visible to VK_SHADER_STAGE_ALL, so vkCmdPushConstants needs no stage
// knowledge (PipelineBindings carries none). Set i = bindings.layouts[i].
Result<VkPipelineLayout> createPipelineLayout(const VulkanContext& context, const PipelineBindings& bindings,
                                              std::string_view debugName);
// Accepts SPIR-V only; the error names code.debugName.
Result<VkShaderModule> createShaderModule(const VulkanContext& context, const ShaderCode& code);
VkShaderStageFlagBits toVkShaderStage(ShaderStage stage);   // exactly one stage bit

// Owns a VkPipeline + VkPipelineLayout (destroyed deferred). Base of every pipeline kind so the command
// list can bind layouts uniformly.
class VulkanPipelineBase {
public:
    VkPipeline pipeline() const { return pipeline_; }
    VkPipelineLayout layout() const { return layout_; }
    VkPipelineBindPoint bindPoint() const { return bindPoint_; }

protected:
    void release();   // deferred destruction of pipeline and layout
    ContextPtr context_;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipelineBindPoint bindPoint_ = VK_PIPELINE_BIND_POINT_COMPUTE;
};

class VulkanComputePipeline final : public IComputePipeline, public VulkanPipelineBase {
public:
    static Result<std::shared_ptr<VulkanComputePipeline>> create(const ContextPtr& context,
                                                                 const ComputePipelineDesc& desc);
    ~VulkanComputePipeline() override { release(); }
    const ComputePipelineDesc& desc() const override { return desc_; }

private:
    explicit VulkanComputePipeline(const ComputePipelineDesc& desc) : desc_(desc) {}
    ComputePipelineDesc desc_;
};

class VulkanGraphicsPipeline final : public IGraphicsPipeline, public VulkanPipelineBase {
public:
    static Result<std::shared_ptr<VulkanGraphicsPipeline>> create(const ContextPtr& context,
                                                                  const GraphicsPipelineDesc& desc);
    ~VulkanGraphicsPipeline() override { release(); }
    const GraphicsPipelineDesc& desc() const override { return desc_; }

private:
    explicit VulkanGraphicsPipeline(const GraphicsPipelineDesc& desc) : desc_(desc) {}
    GraphicsPipelineDesc desc_;
};

inline VulkanComputePipeline* toVk(const ComputePipelineHandle& p) { return static_cast<VulkanComputePipeline*>(p.get()); }
inline VulkanGraphicsPipeline* toVk(const GraphicsPipelineHandle& p) { return static_cast<VulkanGraphicsPipeline*>(p.get()); }

}  // namespace caustics::rhi::vulkan
