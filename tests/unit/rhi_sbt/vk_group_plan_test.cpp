// StateObjectDesc -> Vulkan shader stages and groups: general groups for raygen/miss/callable exports,
// triangle/procedural hit groups pointing at the right stages, and errors that name what is wrong.
#include <gtest/gtest.h>

#include "vk_state_object.h"

namespace caustics::rhi::vulkan {
namespace {

StateObjectDesc sampleDesc() {
    StateObjectDesc desc;
    desc.debugName = "sample";
    ShaderLibraryDesc lib;
    lib.exports = {{"rayGen", "main", ShaderStage::RayGen},
                   {"miss", "main", ShaderStage::Miss},
                   {"chit", "main", ShaderStage::ClosestHit},
                   {"ahit", "main", ShaderStage::AnyHit},
                   {"isect", "main", ShaderStage::Intersection},
                   {"call", "main", ShaderStage::Callable}};
    desc.libraries.push_back(lib);
    desc.hitGroups.push_back({"tri", HitGroupType::Triangles, "chit", "ahit", ""});
    desc.hitGroups.push_back({"proc", HitGroupType::Procedural, "", "ahit", "isect"});
    return desc;
}

TEST(VulkanRayTracingGroups, GeneralExportsAndHitGroupsBecomeGroups) {
    auto plan = planRayTracingGroups(sampleDesc());
    ASSERT_TRUE(plan) << plan.message();
    EXPECT_EQ(plan->stages.size(), 6u);
    ASSERT_EQ(plan->groups.size(), 5u);   // rayGen, miss, call, tri, proc
    const auto& rayGen = plan->groups[plan->groupByName.at("rayGen")];
    EXPECT_EQ(rayGen.type, VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR);
    EXPECT_EQ(rayGen.generalShader, 0u);
    const auto& tri = plan->groups[plan->groupByName.at("tri")];
    EXPECT_EQ(tri.type, VK_RAY_TRACING_SHADER_GROUP_TYPE_TRIANGLES_HIT_GROUP_KHR);
    EXPECT_EQ(tri.closestHitShader, 2u);
    EXPECT_EQ(tri.anyHitShader, 3u);
    EXPECT_EQ(tri.intersectionShader, VK_SHADER_UNUSED_KHR);
    const auto& proc = plan->groups[plan->groupByName.at("proc")];
    EXPECT_EQ(proc.type, VK_RAY_TRACING_SHADER_GROUP_TYPE_PROCEDURAL_HIT_GROUP_KHR);
    EXPECT_EQ(proc.closestHitShader, VK_SHADER_UNUSED_KHR);
    EXPECT_EQ(proc.intersectionShader, 4u);
    EXPECT_EQ(plan->groupByName.count("chit"), 0u);   // hit shaders have no group of their own
}

TEST(VulkanRayTracingGroups, UnknownHitGroupExportNamesGroupAndExport) {
    StateObjectDesc desc = sampleDesc();
    desc.hitGroups.push_back({"broken", HitGroupType::Triangles, "nope", "", ""});
    auto plan = planRayTracingGroups(desc);
    ASSERT_FALSE(plan);
    EXPECT_NE(plan.message().find("'broken'"), std::string::npos) << plan.message();
    EXPECT_NE(plan.message().find("'nope'"), std::string::npos) << plan.message();
}

TEST(VulkanRayTracingGroups, ExportOfWrongStageInHitGroupIsRefused) {
    StateObjectDesc desc = sampleDesc();
    desc.hitGroups.push_back({"wrong", HitGroupType::Triangles, "miss", "", ""});
    auto plan = planRayTracingGroups(desc);
    ASSERT_FALSE(plan);
    EXPECT_NE(plan.message().find("miss shader"), std::string::npos) << plan.message();
}

TEST(VulkanRayTracingGroups, ProceduralGroupWithoutIntersectionIsRefused) {
    StateObjectDesc desc = sampleDesc();
    desc.hitGroups.push_back({"noIsect", HitGroupType::Procedural, "chit", "", ""});
    EXPECT_FALSE(planRayTracingGroups(desc));
}

TEST(VulkanRayTracingGroups, DuplicateNamesAreRefused) {
    StateObjectDesc desc = sampleDesc();
    desc.hitGroups.push_back({"miss", HitGroupType::Triangles, "chit", "", ""});
    EXPECT_FALSE(planRayTracingGroups(desc));
}

TEST(VulkanRayTracingGroups, StateObjectWithoutRayGenIsRefused) {
    StateObjectDesc desc = sampleDesc();
    desc.libraries[0].exports.erase(desc.libraries[0].exports.begin());
    auto plan = planRayTracingGroups(desc);
    ASSERT_FALSE(plan);
    EXPECT_NE(plan.message().find("raygen"), std::string::npos);
}

}  // namespace
}  // namespace caustics::rhi::vulkan
