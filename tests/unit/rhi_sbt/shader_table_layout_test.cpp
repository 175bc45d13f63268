// Shader-binding-table layout rules (DXR spec "Shader tables"; Vulkan vkCmdTraceRaysKHR valid usage
// VUID-vkCmdTraceRaysKHR-size-04023 and -pRayGenShaderBindingTable-03682, -stride-03686, -03690).
#include <gtest/gtest.h>

#include <random>

#include "caustics/rhi/shader_table_layout.h"

namespace caustics::rhi {
namespace {

// lavapipe (Mesa 25): shaderGroupHandleSize 32, handle alignment 32, base alignment 32.
constexpr ShaderTableAlignment kLavapipe{32, 32, 32, 4096};
// NVIDIA Vulkan and D3D12: handle 32, record alignment 32, table alignment 64.
constexpr ShaderTableAlignment kNvidia{32, 32, 64, 4096};

ShaderTableLayout layoutOf(const ShaderTableAlignment& a, const ShaderTableCounts& c) {
    ShaderTableLayout layout;
    EXPECT_TRUE(computeShaderTableLayout(a, c, layout));
    return layout;
}

TEST(ShaderTableLayout, LavapipeRegionsArePackedBackToBack) {
    ShaderTableCounts counts;
    counts.missCount = 2;
    counts.hitGroupCount = 3;
    ShaderTableLayout l = layoutOf(kLavapipe, counts);
    EXPECT_EQ(l.rayGen.offset, 0u);
    EXPECT_EQ(l.rayGen.stride, 32u);
    EXPECT_EQ(l.miss.offset, 32u);
    EXPECT_EQ(l.miss.size, 64u);
    EXPECT_EQ(l.hitGroup.offset, 96u);
    EXPECT_EQ(l.hitGroup.size, 96u);
    EXPECT_EQ(l.totalBytes, 192u);
}

TEST(ShaderTableLayout, NvidiaRegionsStartOn64ByteBoundaries) {
    ShaderTableCounts counts;
    counts.missCount = 1;
    counts.hitGroupCount = 3;
    counts.callableCount = 1;
    ShaderTableLayout l = layoutOf(kNvidia, counts);
    EXPECT_EQ(l.rayGen.offset, 0u);
    EXPECT_EQ(l.miss.offset, 64u);     // raygen ends at 32, rounded up to 64
    EXPECT_EQ(l.hitGroup.offset, 128u);  // miss ends at 96
    EXPECT_EQ(l.hitGroup.size, 96u);
    EXPECT_EQ(l.callable.offset, 256u);  // hit groups end at 224
    EXPECT_EQ(l.totalBytes, 320u);
}

TEST(ShaderTableLayout, LocalDataWidensStrideToHandleAlignment) {
    ShaderTableCounts counts;
    counts.hitGroupCount = 2;
    counts.hitGroupDataBytes = 4;    // 32 + 4 = 36 -> 64
    counts.missCount = 1;
    counts.missDataBytes = 33;       // 32 + 33 = 65 -> 96
    ShaderTableLayout l = layoutOf(kLavapipe, counts);
    EXPECT_EQ(l.hitGroup.stride, 64u);
    EXPECT_EQ(l.hitGroup.size, 128u);
    EXPECT_EQ(l.miss.stride, 96u);
    EXPECT_EQ(l.rayGen.stride, 32u);  // regions are independent: raygen carries no data
}

TEST(ShaderTableLayout, LocalDataExactlyFillingARecordKeepsStride) {
    ShaderTableCounts counts;
    counts.hitGroupCount = 1;
    counts.hitGroupDataBytes = 32;   // 32 + 32 = 64, already aligned
    EXPECT_EQ(layoutOf(kNvidia, counts).hitGroup.stride, 64u);
}

TEST(ShaderTableLayout, RayGenRegionSizeEqualsStride) {
    for (uint32_t data : {0u, 1u, 16u, 40u, 200u}) {
        for (const ShaderTableAlignment& a : {kLavapipe, kNvidia}) {
            ShaderTableCounts counts;
            counts.rayGenDataBytes = data;
            counts.missCount = 1;
            ShaderTableLayout l = layoutOf(a, counts);
            EXPECT_EQ(l.rayGen.count, 1u);
            EXPECT_EQ(l.rayGen.size, l.rayGen.stride) << "raygen data " << data;
            EXPECT_GE(l.rayGen.stride, 32u + data);
        }
    }
}

TEST(ShaderTableLayout, EmptyRegionsHaveZeroSizeAndStride) {
    ShaderTableLayout l = layoutOf(kNvidia, ShaderTableCounts{});
    EXPECT_EQ(l.miss.size, 0u);
    EXPECT_EQ(l.miss.stride, 0u);
    EXPECT_EQ(l.hitGroup.size, 0u);
    EXPECT_EQ(l.callable.size, 0u);
    EXPECT_EQ(l.totalBytes, 64u);   // the raygen record rounded to the base alignment
}

// For random counts and data sizes, every region starts on the base alignment, strides are multiples
// of the handle alignment, regions do not overlap and all lie inside totalBytes.
TEST(ShaderTableLayout, RegionsAreAlignedDisjointAndInsideTheTable) {
    std::mt19937 rng(1234);
    std::uniform_int_distribution<uint32_t> count(0, 9), data(0, 300);
    for (const ShaderTableAlignment& a : {kLavapipe, kNvidia}) {
        for (int trial = 0; trial < 500; ++trial) {
            ShaderTableCounts c;
            c.missCount = count(rng);
            c.hitGroupCount = count(rng);
            c.callableCount = count(rng);
            c.rayGenDataBytes = data(rng);
            c.missDataBytes = data(rng);
            c.hitGroupDataBytes = data(rng);
            c.callableDataBytes = data(rng);
            ShaderTableLayout l = layoutOf(a, c);
            const ShaderTableRegion* regions[] = {&l.rayGen, &l.miss, &l.hitGroup, &l.callable};
            uint64_t end = 0;
            for (const ShaderTableRegion* r : regions) {
                if (r->count == 0) continue;
                EXPECT_EQ(r->offset % a.baseAlignment, 0u);
                EXPECT_EQ(r->stride % a.handleAlignment, 0u);
                EXPECT_EQ(r->size, r->stride * r->count);
                EXPECT_GE(r->offset, end);   // regions come in order and never overlap
                end = r->offset + r->size;
            }
            EXPECT_LE(end, l.totalBytes);
            EXPECT_EQ(l.totalBytes % a.baseAlignment, 0u);
        }
    }
}

TEST(ShaderTableLayout, StrideAboveMaxStrideIsRefusedAndLeavesOutputUntouched) {
    ShaderTableCounts counts;
    counts.hitGroupCount = 1;
    counts.hitGroupDataBytes = 4096 - 32 + 1;   // 32 + 4065 -> stride 4128 > 4096
    ShaderTableLayout out;
    out.totalBytes = 777;
    EXPECT_FALSE(computeShaderTableLayout(kNvidia, counts, out));
    EXPECT_EQ(out.totalBytes, 777u);
}

TEST(ShaderTableLayout, StrideEqualToMaxStrideIsAccepted) {
    ShaderTableCounts counts;
    counts.callableCount = 1;
    counts.callableDataBytes = 4096 - 32;
    ShaderTableLayout out;
    ASSERT_TRUE(computeShaderTableLayout(kLavapipe, counts, out));
    EXPECT_EQ(out.callable.stride, 4096u);
}

}  // namespace
}  // namespace caustics::rhi
