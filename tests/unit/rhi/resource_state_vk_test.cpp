#include "vk_resource_state.h"

#include <gtest/gtest.h>

namespace caustics::rhi::vulkan {
namespace {

TEST(VulkanStateTranslation, UndefinedWaitsForNothingAndDiscards) {
    VkStateInfo s = translateState(ResourceState::Undefined);
    EXPECT_EQ(s.stages, VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT);
    EXPECT_EQ(s.access, VK_ACCESS_2_NONE);
    EXPECT_EQ(s.layout, VK_IMAGE_LAYOUT_UNDEFINED);
}

TEST(VulkanStateTranslation, CopyStatesUseTransferStageAndLayouts) {
    VkStateInfo src = translateState(ResourceState::CopySource);
    VkStateInfo dst = translateState(ResourceState::CopyDest);
    EXPECT_EQ(src.stages, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT);
    EXPECT_EQ(src.access, VK_ACCESS_2_TRANSFER_READ_BIT);
    EXPECT_EQ(src.layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    EXPECT_EQ(dst.access, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    EXPECT_EQ(dst.layout, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
}

TEST(VulkanStateTranslation, UnorderedAccessIsGeneralReadWriteInEveryShaderStage) {
    VkStateInfo s = translateState(ResourceState::UnorderedAccess);
    EXPECT_EQ(s.layout, VK_IMAGE_LAYOUT_GENERAL);
    EXPECT_EQ(s.access, VK_ACCESS_2_SHADER_READ_BIT | VK_ACCESS_2_SHADER_WRITE_BIT);
    for (VkPipelineStageFlags2 stage : {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                                        VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR})
        EXPECT_TRUE(s.stages & stage);
}

TEST(VulkanStateTranslation, RenderTargetAndDepthUseAttachmentStagesAndLayouts) {
    VkStateInfo rt = translateState(ResourceState::RenderTarget);
    EXPECT_EQ(rt.stages, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT);
    EXPECT_EQ(rt.layout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    VkStateInfo dw = translateState(ResourceState::DepthWrite);
    EXPECT_TRUE(dw.access & VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
    EXPECT_EQ(dw.layout, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
}

TEST(VulkanStateTranslation, ShaderResourceOfDepthTextureUsesDepthReadOnlyLayout) {
    EXPECT_EQ(translateState(ResourceState::ShaderResource, false).layout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    EXPECT_EQ(translateState(ResourceState::ShaderResource, true).layout,
              VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
}

TEST(VulkanStateTranslation, AccelStructStatesUseBuildAndTraceStagesWithAsAccess) {
    VkStateInfo w = translateState(ResourceState::AccelStructWrite);
    EXPECT_EQ(w.stages, VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR);
    EXPECT_TRUE(w.access & VK_ACCESS_2_ACCELERATION_STRUCTURE_WRITE_BIT_KHR);
    VkStateInfo r = translateState(ResourceState::AccelStructRead);
    EXPECT_TRUE(r.stages & VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR);
    EXPECT_TRUE(r.stages & VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR);
    EXPECT_EQ(r.access, VK_ACCESS_2_ACCELERATION_STRUCTURE_READ_BIT_KHR);
    VkStateInfo in = translateState(ResourceState::AccelStructBuildInput);
    EXPECT_EQ(in.stages, VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR);
}

TEST(VulkanStateTranslation, CombinedStatesUnionAccessAndPickTheSpecificLayout) {
    VkStateInfo s = translateState(ResourceState::DepthRead | ResourceState::ShaderResource, true);
    EXPECT_EQ(s.layout, VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
    EXPECT_TRUE(s.access & VK_ACCESS_2_SHADER_READ_BIT);
    EXPECT_TRUE(s.access & VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT);
    VkStateInfo vb = translateState(ResourceState::VertexBuffer | ResourceState::IndexBuffer);
    EXPECT_EQ(vb.access, VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_2_INDEX_READ_BIT);
}

TEST(VulkanStateTranslation, ShaderTableIsReadByRayTracingStage) {
    VkStateInfo s = translateState(ResourceState::ShaderTable);
    EXPECT_EQ(s.stages, VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR);
    EXPECT_EQ(s.access, VK_ACCESS_2_SHADER_BINDING_TABLE_READ_BIT_KHR);
}

// The render graph's compute -> ray tracing, raster -> compute and copy -> compute chains
// (RenderGraphBarrierStages.*) become these masks: only the producer's and the consumer's stages.
TEST(VulkanStateTranslation, WorkNarrowsShaderStatesToTheStagesThatWorkRuns) {
    EXPECT_EQ(translateState(ResourceState::UnorderedAccess, false, PipelineStages::Compute).stages,
              VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
    EXPECT_EQ(translateState(ResourceState::ShaderResource, false, PipelineStages::RayTracing).stages,
              VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR);
    EXPECT_EQ(translateState(ResourceState::ShaderResource, false, PipelineStages::Raster).stages,
              VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
    EXPECT_EQ(translateState(ResourceState::RenderTarget, false, PipelineStages::Raster).stages,
              VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT);
    EXPECT_EQ(translateState(ResourceState::CopyDest, false, PipelineStages::Copy).stages,
              VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT);
    EXPECT_EQ(translateState(ResourceState::AccelStructRead, false, PipelineStages::RayTracing).stages,
              VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR);
    EXPECT_EQ(translateState(ResourceState::IndirectArgument, false, PipelineStages::RayTracing).stages,
              VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT);
    // The access and layout do not change with the work.
    EXPECT_EQ(translateState(ResourceState::UnorderedAccess, false, PipelineStages::Compute).access,
              VK_ACCESS_2_SHADER_READ_BIT | VK_ACCESS_2_SHADER_WRITE_BIT);
    EXPECT_EQ(translateState(ResourceState::ShaderResource, false, PipelineStages::Compute).layout,
              VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

TEST(VulkanStateTranslation, WorkThatCannotUseTheStateLeavesItsStagesWhole) {
    // A colour attachment "used by compute" is a graph inconsistency: no stage is dropped.
    EXPECT_EQ(translateState(ResourceState::RenderTarget, false, PipelineStages::Compute).stages,
              translateState(ResourceState::RenderTarget).stages);
    EXPECT_EQ(translateState(ResourceState::UnorderedAccess, false, PipelineStages::None).stages,
              translateState(ResourceState::UnorderedAccess).stages);
}

TEST(VulkanStateTranslation, AliasingSourceIsEveryStageOfTheEarlierWorkOrAllCommands) {
    EXPECT_EQ(stagesOfWork(PipelineStages::None), VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT);
    EXPECT_EQ(stagesOfWork(PipelineStages::Copy), VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT);
    EXPECT_EQ(stagesOfWork(PipelineStages::Compute | PipelineStages::RayTracing),
              VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT |
                  VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR);
    EXPECT_FALSE(stagesOfWork(PipelineStages::Raster | PipelineStages::Compute) & VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT);
}

}  // namespace
}  // namespace caustics::rhi::vulkan
