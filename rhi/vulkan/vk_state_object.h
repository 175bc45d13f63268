#pragma once
// Ray-tracing state object -> one VkPipeline (vkCreateRayTracingPipelinesKHR). Every export of every
// library becomes a shader stage; raygen/miss/callable exports become general shader groups and hit
// groups become triangle or procedural hit groups. Shader identifiers are the group handles.
#include <vulkan/vulkan.h>

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "caustics/rhi/state_object.h"
#include "vk_context.h"
#include "vk_pipeline.h"

namespace caustics::rhi::vulkan {

// The groups of a state object, in pipeline order; device-free so the translation is unit-testable.
struct RayTracingGroupPlan {
    struct Stage {
        uint32_t library = 0;
        uint32_t exportIndex = 0;
        ShaderStage stage = ShaderStage::RayGen;
    };
    std::vector<Stage> stages;                                // pStages order
    std::vector<VkRayTracingShaderGroupCreateInfoKHR> groups; // pGroups order
    std::unordered_map<std::string, uint32_t> groupByName;    // export or hit-group name -> group index
};
// Errors name the state object and the offending export or hit group.
Result<RayTracingGroupPlan> planRayTracingGroups(const StateObjectDesc& desc);

class VulkanStateObject final : public IStateObject, public VulkanPipelineBase {
public:
    static Result<std::shared_ptr<VulkanStateObject>> create(const ContextPtr& context, const StateObjectDesc& desc);
    ~VulkanStateObject() override { release(); }

    const StateObjectDesc& desc() const override { return desc_; }
    std::vector<uint8_t> shaderIdentifier(const std::string& exportName) const override;
    // Group handle bytes (handleSize) or nullptr for an unknown name.
    const uint8_t* groupHandle(const std::string& name) const;
    uint32_t handleSize() const { return handleSize_; }

private:
    explicit VulkanStateObject(const StateObjectDesc& desc) : desc_(desc) {}
    StateObjectDesc desc_;
    std::unordered_map<std::string, uint32_t> groupByName_;
    std::vector<uint8_t> handles_;   // groupCount * handleSize
    uint32_t handleSize_ = 0;
};

inline VulkanStateObject* toVk(const StateObjectHandle& s) { return static_cast<VulkanStateObject*>(s.get()); }

}  // namespace caustics::rhi::vulkan
