#include <gtest/gtest.h>

#include "resource_states.h"

namespace caustics::rhi::d3d12 {
namespace {

TEST(D3D12Barriers, ShaderResourceIsReadableByPixelAndNonPixelStages) {
    EXPECT_EQ(toD3D12States(ResourceState::ShaderResource),
              D3D12_RESOURCE_STATE_PIXEL_SHADER_RESOURCE | D3D12_RESOURCE_STATE_NON_PIXEL_SHADER_RESOURCE);
}

// The render graph flags the first barrier of a transient placed over memory another transient used;
// D3D12 needs an aliasing barrier then, besides the transition (D3D12 "Using resource barriers").
TEST(D3D12Barriers, AliasingFlagAsksForAnAliasingBarrierBeforeTheTransition) {
    BarrierPlan plan = planBarrier(ResourceState::Undefined, ResourceState::UnorderedAccess,
                                   D3D12_RESOURCE_STATE_COMMON, /*aliasing=*/true);
    EXPECT_TRUE(plan.aliasing);
    EXPECT_TRUE(plan.transition);
    EXPECT_EQ(plan.after, D3D12_RESOURCE_STATE_UNORDERED_ACCESS);
    EXPECT_FALSE(planBarrier(ResourceState::Undefined, ResourceState::UnorderedAccess, D3D12_RESOURCE_STATE_COMMON)
                     .aliasing);
}

TEST(D3D12Barriers, SingleStatesMapOneToOne) {
    EXPECT_EQ(toD3D12States(ResourceState::UnorderedAccess), D3D12_RESOURCE_STATE_UNORDERED_ACCESS);
    EXPECT_EQ(toD3D12States(ResourceState::RenderTarget), D3D12_RESOURCE_STATE_RENDER_TARGET);
    EXPECT_EQ(toD3D12States(ResourceState::DepthWrite), D3D12_RESOURCE_STATE_DEPTH_WRITE);
    EXPECT_EQ(toD3D12States(ResourceState::DepthRead), D3D12_RESOURCE_STATE_DEPTH_READ);
    EXPECT_EQ(toD3D12States(ResourceState::CopySource), D3D12_RESOURCE_STATE_COPY_SOURCE);
    EXPECT_EQ(toD3D12States(ResourceState::CopyDest), D3D12_RESOURCE_STATE_COPY_DEST);
    EXPECT_EQ(toD3D12States(ResourceState::IndirectArgument), D3D12_RESOURCE_STATE_INDIRECT_ARGUMENT);
    EXPECT_EQ(toD3D12States(ResourceState::Common), D3D12_RESOURCE_STATE_COMMON);
}

TEST(D3D12Barriers, AccelStructStatesAllMapToTheRaytracingState) {
    EXPECT_EQ(toD3D12States(ResourceState::AccelStructRead), D3D12_RESOURCE_STATE_RAYTRACING_ACCELERATION_STRUCTURE);
    EXPECT_EQ(toD3D12States(ResourceState::AccelStructWrite), D3D12_RESOURCE_STATE_RAYTRACING_ACCELERATION_STRUCTURE);
}

TEST(D3D12Barriers, ShaderTablesAndBuildInputsAreNonPixelShaderResources) {
    EXPECT_EQ(toD3D12States(ResourceState::ShaderTable), D3D12_RESOURCE_STATE_NON_PIXEL_SHADER_RESOURCE);
    EXPECT_EQ(toD3D12States(ResourceState::AccelStructBuildInput), D3D12_RESOURCE_STATE_NON_PIXEL_SHADER_RESOURCE);
}

TEST(D3D12Barriers, CombinedReadStatesAreOred) {
    EXPECT_EQ(toD3D12States(ResourceState::CopySource | ResourceState::IndexBuffer),
              D3D12_RESOURCE_STATE_COPY_SOURCE | D3D12_RESOURCE_STATE_INDEX_BUFFER);
}

TEST(D3D12Barriers, StateChangeIsATransition) {
    BarrierPlan p = planBarrier(ResourceState::UnorderedAccess, ResourceState::ShaderResource,
                                D3D12_RESOURCE_STATE_COMMON);
    EXPECT_TRUE(p.transition);
    EXPECT_FALSE(p.uav);
    EXPECT_EQ(p.before, D3D12_RESOURCE_STATE_UNORDERED_ACCESS);
}

TEST(D3D12Barriers, UavToUavIsAUavBarrierNotATransition) {
    BarrierPlan p = planBarrier(ResourceState::UnorderedAccess, ResourceState::UnorderedAccess,
                                D3D12_RESOURCE_STATE_UNORDERED_ACCESS);
    EXPECT_FALSE(p.transition);
    EXPECT_TRUE(p.uav);
}

TEST(D3D12Barriers, UndefinedBeforeUsesTheTrackedState) {
    BarrierPlan p = planBarrier(ResourceState::Undefined, ResourceState::CopyDest, D3D12_RESOURCE_STATE_RENDER_TARGET);
    EXPECT_TRUE(p.transition);
    EXPECT_EQ(p.before, D3D12_RESOURCE_STATE_RENDER_TARGET);
    EXPECT_EQ(p.after, D3D12_RESOURCE_STATE_COPY_DEST);
}

TEST(D3D12Barriers, UnchangedReadStateNeedsNoBarrier) {
    BarrierPlan p = planBarrier(ResourceState::ShaderResource, ResourceState::ShaderResource,
                                D3D12_RESOURCE_STATE_COMMON);
    EXPECT_FALSE(p.transition);
    EXPECT_FALSE(p.uav);
}

TEST(D3D12Barriers, AccelStructBuildThenTraceIsAUavBarrier) {
    BarrierPlan p = planAccelStructBarrier(ResourceState::AccelStructWrite, ResourceState::AccelStructRead);
    EXPECT_TRUE(p.uav);
    EXPECT_FALSE(p.transition);
}

TEST(D3D12Barriers, AccelStructReadToReadNeedsNothing) {
    EXPECT_FALSE(planAccelStructBarrier(ResourceState::AccelStructRead, ResourceState::AccelStructRead).uav);
}

}  // namespace
}  // namespace caustics::rhi::d3d12
