// AccelStructDesc -> Vulkan build geometry: flags, primitive counts, index types, and the errors for
// malformed geometry (device-free; buffer addresses are zero without buffers).
#include <gtest/gtest.h>

#include "vk_accel_struct.h"

namespace caustics::rhi::vulkan {
namespace {

TEST(VulkanAccelGeometry, NoDuplicateAnyHitAndOpaqueMapToGeometryFlags) {
    AccelStructDesc desc;
    desc.geometries.push_back(GeometryDesc::fromAabbs({nullptr, 0, 100, 24}, GeometryFlags::NoDuplicateAnyHit));
    desc.geometries.push_back(GeometryDesc::fromAabbs({nullptr, 0, 5, 32}, GeometryFlags::Opaque));
    auto info = describeBottomLevel(desc);
    ASSERT_TRUE(info) << info.message();
    EXPECT_EQ(info->geometries[0].flags, VkGeometryFlagsKHR(VK_GEOMETRY_NO_DUPLICATE_ANY_HIT_INVOCATION_BIT_KHR));
    EXPECT_EQ(info->geometries[1].flags, VkGeometryFlagsKHR(VK_GEOMETRY_OPAQUE_BIT_KHR));
    EXPECT_EQ(info->geometries[0].geometryType, VK_GEOMETRY_TYPE_AABBS_KHR);
    EXPECT_EQ(info->geometries[1].geometry.aabbs.stride, 32u);
    EXPECT_EQ(info->primitiveCounts, (std::vector<uint32_t>{100, 5}));
}

TEST(VulkanAccelGeometry, NonIndexedTrianglesCountVerticesAndUseNoIndexType) {
    AccelStructDesc desc;
    TriangleGeometry tri;
    tri.vertexCount = 9;
    desc.geometries.push_back(GeometryDesc::fromTriangles(tri));
    auto info = describeBottomLevel(desc);
    ASSERT_TRUE(info) << info.message();
    EXPECT_EQ(info->geometries[0].geometry.triangles.indexType, VK_INDEX_TYPE_NONE_KHR);
    EXPECT_EQ(info->geometries[0].geometry.triangles.maxVertex, 8u);
    EXPECT_EQ(info->geometries[0].geometry.triangles.vertexFormat, VK_FORMAT_R32G32B32_SFLOAT);
    EXPECT_EQ(info->ranges[0].primitiveCount, 3u);
}

TEST(VulkanAccelGeometry, TriangleCornersNotMultipleOfThreeAreAnError) {
    AccelStructDesc desc;
    desc.debugName = "bad mesh";
    TriangleGeometry tri;
    tri.vertexCount = 7;
    desc.geometries.push_back(GeometryDesc::fromTriangles(tri));
    auto info = describeBottomLevel(desc);
    ASSERT_FALSE(info);
    EXPECT_NE(info.message().find("bad mesh"), std::string::npos) << info.message();
}

TEST(VulkanAccelGeometry, TopLevelDescribesInstancesByAddress) {
    AccelGeometryInfo info = describeTopLevel(0x1000, 42);
    EXPECT_EQ(info.geometries[0].geometryType, VK_GEOMETRY_TYPE_INSTANCES_KHR);
    EXPECT_EQ(info.geometries[0].geometry.instances.data.deviceAddress, 0x1000u);
    EXPECT_EQ(info.ranges[0].primitiveCount, 42u);
}

TEST(VulkanAccelGeometry, BuildFlagsMapAndFastTraceWinsOverFastBuild) {
    const auto flags = toVkBuildFlags(AccelBuildFlags::AllowUpdate | AccelBuildFlags::AllowCompaction |
                                      AccelBuildFlags::PreferFastTrace | AccelBuildFlags::PreferFastBuild);
    EXPECT_TRUE(flags & VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_UPDATE_BIT_KHR);
    EXPECT_TRUE(flags & VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_COMPACTION_BIT_KHR);
    EXPECT_TRUE(flags & VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR);
    // Vulkan forbids both preference bits together (VUID-VkAccelerationStructureBuildGeometryInfoKHR-flags-03796).
    EXPECT_FALSE(flags & VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_BUILD_BIT_KHR);
}

}  // namespace
}  // namespace caustics::rhi::vulkan
