#pragma once
// ResourceState -> Vulkan synchronization2 terms. Device-free (only Vulkan types), unit-tested in
// tests/unit/rhi/resource_state_vk_test.cpp.
#include <vulkan/vulkan.h>

#include "caustics/rhi/pipeline_stages.h"
#include "caustics/rhi/resource_state.h"

namespace caustics::rhi::vulkan {

struct VkStateInfo {
    VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 access = VK_ACCESS_2_NONE;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;   // meaningful for textures only
};

// Combined states (several bits) OR their stages and access; the layout is the one of the most
// specific bit (e.g. DepthRead|ShaderResource -> DEPTH_STENCIL_READ_ONLY_OPTIMAL). `isDepth` selects
// depth layouts for ShaderResource on depth textures.
// `work` narrows the stages to those that kind of work runs (ShaderResource read by Compute:
// COMPUTE_SHADER only); a state none of whose stages that work runs keeps all of its own (a
// conservative answer for a combination the graph should not produce). None = no narrowing.
VkStateInfo translateState(ResourceState state, bool isDepth = false, PipelineStages work = PipelineStages::None);

// Every Vulkan stage the given kinds of work run (ALL_COMMANDS for None): the source scope of an
// aliasing barrier, which waits for whatever work last used the memory.
VkPipelineStageFlags2 stagesOfWork(PipelineStages work);

}  // namespace caustics::rhi::vulkan
