#include "vk_resource_state.h"

namespace caustics::rhi::vulkan {
namespace {

constexpr VkPipelineStageFlags2 kAllShaders =
    VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT |
    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR;

struct BitInfo {
    ResourceState bit;
    VkPipelineStageFlags2 stages;
    VkAccessFlags2 access;
    VkImageLayout layout;
    int layoutPriority;   // higher wins when several bits are combined
};

// One row per ResourceState bit (Vulkan spec 7.1.2 "Pipeline Stages", 7.1.3 "Access Types",
// 12.4 "Image Layouts"). Shader-visible states include the ray-tracing stage because any stage may
// read them (the RHI states carry no stage).
const BitInfo kBits[] = {
    {ResourceState::Common, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
     VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT, VK_IMAGE_LAYOUT_GENERAL, 0},
    {ResourceState::ConstantBuffer, kAllShaders, VK_ACCESS_2_UNIFORM_READ_BIT, VK_IMAGE_LAYOUT_UNDEFINED, 0},
    {ResourceState::VertexBuffer, VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT,
     VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT, VK_IMAGE_LAYOUT_UNDEFINED, 0},
    {ResourceState::IndexBuffer, VK_PIPELINE_STAGE_2_INDEX_INPUT_BIT, VK_ACCESS_2_INDEX_READ_BIT,
     VK_IMAGE_LAYOUT_UNDEFINED, 0},
    {ResourceState::IndirectArgument, VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT,
     VK_IMAGE_LAYOUT_UNDEFINED, 0},
    {ResourceState::ShaderResource, kAllShaders, VK_ACCESS_2_SHADER_READ_BIT,
     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, 1},
    {ResourceState::UnorderedAccess, kAllShaders, VK_ACCESS_2_SHADER_READ_BIT | VK_ACCESS_2_SHADER_WRITE_BIT,
     VK_IMAGE_LAYOUT_GENERAL, 5},
    {ResourceState::RenderTarget, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
     VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
     VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, 5},
    {ResourceState::DepthWrite,
     VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
     VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
     VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, 5},
    {ResourceState::DepthRead,
     VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
     VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT, VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL, 3},
    {ResourceState::CopySource, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
     VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, 4},
    {ResourceState::CopyDest, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 5},
    // An acceleration structure is read by builds (a TLAS reads its BLASes; updates read the source)
    // and by traversal in ray-tracing shaders (VK_KHR_acceleration_structure "Synchronization").
    {ResourceState::AccelStructRead,
     VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR | VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR |
         VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
     VK_ACCESS_2_ACCELERATION_STRUCTURE_READ_BIT_KHR, VK_IMAGE_LAYOUT_UNDEFINED, 0},
    {ResourceState::AccelStructWrite, VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
     VK_ACCESS_2_ACCELERATION_STRUCTURE_WRITE_BIT_KHR | VK_ACCESS_2_ACCELERATION_STRUCTURE_READ_BIT_KHR,
     VK_IMAGE_LAYOUT_UNDEFINED, 0},
    // Build inputs (vertices, indices, AABBs, instances) are read as shader reads by the build stage.
    {ResourceState::AccelStructBuildInput, VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
     VK_ACCESS_2_SHADER_READ_BIT, VK_IMAGE_LAYOUT_UNDEFINED, 0},
    {ResourceState::ShaderTable, VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR,
     VK_ACCESS_2_SHADER_BINDING_TABLE_READ_BIT_KHR, VK_IMAGE_LAYOUT_UNDEFINED, 0},
    {ResourceState::Present, VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, VK_ACCESS_2_NONE,
     VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, 6},
};

}  // namespace

VkPipelineStageFlags2 stagesOfWork(PipelineStages work) {
    if (work == PipelineStages::None) return VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    VkPipelineStageFlags2 out = VK_PIPELINE_STAGE_2_NONE;
    // Vulkan spec 7.1.2 "Pipeline Stages": the stages each kind of command executes.
    if (hasAny(work, PipelineStages::Raster))
        out |= VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_VERTEX_INPUT_BIT |
               VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT |
               VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT |
               VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
    if (hasAny(work, PipelineStages::Compute))
        out |= VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    if (hasAny(work, PipelineStages::RayTracing))
        out |= VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR;
    if (hasAny(work, PipelineStages::Copy)) out |= VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
    if (hasAny(work, PipelineStages::AccelStructBuild))
        out |= VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR;   // copies too (no maintenance1)
    return out;
}

VkStateInfo translateState(ResourceState state, bool isDepth, PipelineStages work) {
    VkStateInfo out;
    if (state == ResourceState::Undefined) {
        // Nothing to wait for; contents are discarded by the layout transition from UNDEFINED.
        out.stages = VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT;
        return out;
    }
    int bestPriority = -1;
    for (const BitInfo& b : kBits) {
        if (!hasAny(state, b.bit)) continue;
        const VkPipelineStageFlags2 narrowed = work == PipelineStages::None ? b.stages : b.stages & stagesOfWork(work);
        out.stages |= narrowed ? narrowed : b.stages;
        out.access |= b.access;
        if (b.layout != VK_IMAGE_LAYOUT_UNDEFINED && b.layoutPriority > bestPriority) {
            bestPriority = b.layoutPriority;
            out.layout = b.layout;
        }
    }
    if (isDepth && out.layout == VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
        out.layout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;
    // Buffer-only states still need a defined layout if applied to a texture; GENERAL is valid for all.
    if (out.layout == VK_IMAGE_LAYOUT_UNDEFINED) out.layout = VK_IMAGE_LAYOUT_GENERAL;
    return out;
}

}  // namespace caustics::rhi::vulkan
