// Shader tables with local data (Vulkan shaderRecordEXT): two hit groups, four hit records with
// different constants selected per instance through hitGroupOffset, a miss record and a raygen record
// with their own constants; every pixel must show the constants of the records that ran for it.
#include <gtest/gtest.h>

#include <cmath>

#include "rt_fixture.h"

namespace caustics::test {
namespace {

using namespace caustics::rhi;

constexpr uint32_t kWidth = 80, kHeight = 8;
constexpr uint32_t kRayGenBase = 100000, kMissValue = 7;
constexpr uint32_t kHitValues[4] = {11, 22, 33, 44};
// Quad i covers x in [1.25 i, 1.25 i + 1]; pixel centres never fall on an edge (multiples of 0.25
// are 4k pixel widths from the origin, centres are at 4k + 0.5).
constexpr float kQuadSpacing = 1.25f;

std::vector<uint8_t> bytesOf(uint32_t v) {
    std::vector<uint8_t> b(4);
    std::memcpy(b.data(), &v, 4);
    return b;
}

StateObjectDesc recordStateObjectDesc(const BindingLayoutHandle& layout) {
    StateObjectDesc desc;
    desc.libraries.push_back(shaderLibrary("rt/record.rgen", "rayGen", ShaderStage::RayGen));
    desc.libraries.push_back(shaderLibrary("rt/record.rmiss", "miss", ShaderStage::Miss));
    desc.libraries.push_back(shaderLibrary("rt/record_a.rchit", "hitA", ShaderStage::ClosestHit));
    desc.libraries.push_back(shaderLibrary("rt/record_b.rchit", "hitB", ShaderStage::ClosestHit));
    desc.hitGroups.push_back({"groupA", HitGroupType::Triangles, "hitA", "", ""});
    desc.hitGroups.push_back({"groupB", HitGroupType::Triangles, "hitB", "", ""});
    desc.maxPayloadBytes = 4;
    desc.globalBindings.layouts = {layout};
    desc.globalBindings.pushConstantBytes = 32;
    desc.localBindings.localDataBytes = 4;
    return desc;
}

TEST_F(RayTracingTest, InstancesSelectHitRecordsAndEachShowsItsLocalConstant) {
    const CpuMesh quad = makeQuad(0.5f);
    std::vector<BufferHandle> keep;
    AccelStructHandle blas = makeTriangleBlas(dev(), quad, AccelBuildFlags::PreferFastTrace, keep);
    ASSERT_TRUE(blas);
    BindingLayoutHandle layout = makeLayout(dev(), 0);
    auto so = dev().createStateObject(recordStateObjectDesc(layout));
    ASSERT_TRUE(so) << so.message();
    ShaderTableDesc tableDesc{so.value()};
    tableDesc.setRayGen("rayGen", bytesOf(kRayGenBase)).addMiss("miss", bytesOf(kMissValue));
    const char* groups[4] = {"groupA", "groupB", "groupA", "groupB"};
    for (int i = 0; i < 4; ++i) tableDesc.addHitGroup(groups[i], bytesOf(kHitValues[i]));
    auto table = dev().createShaderTable(tableDesc);
    ASSERT_TRUE(table) << table.message();

    std::vector<InstanceDesc> instances(4);
    for (uint32_t i = 0; i < 4; ++i) {
        instances[i].transform[0][3] = kQuadSpacing * float(i) + 0.5f;
        instances[i].transform[1][3] = 0.5f;
        instances[i].hitGroupOffset = i;
        instances[i].blasAddress = blas->deviceAddress();
    }
    AccelStructDesc tlasDesc;
    tlasDesc.isTopLevel = true;
    tlasDesc.maxInstances = 4;
    auto tlas = dev().createAccelStruct(tlasDesc);
    ASSERT_TRUE(tlas) << tlas.message();

    const uint64_t outBytes = kWidth * kHeight * 4;
    BufferHandle out = makeOutputBuffer(dev(), outBytes, "values");
    BufferHandle readback = makeReadbackBuffer(dev(), outBytes);
    auto set = dev().createBindingSet(
        BindingSetDesc().add(BindingSetItem::accelStructItem(0, tlas.value())).add(BindingSetItem::storageBuffer(1, out)),
        layout);
    ASSERT_TRUE(set) << set.message();
    const float grid[8] = {-0.25f, 0.0f, 0, 0, 5.0f / kWidth, 1.0f / kHeight, 0, 0};

    ASSERT_TRUE(runAndWait(dev(), [&](ICommandList& cmd) {
        cmd.buildBottomLevel(blas);
        cmd.barrier(AccelStructBarrier{blas, ResourceState::AccelStructWrite, ResourceState::AccelStructRead});
        cmd.buildTopLevel(tlas.value(), instances);
        cmd.barrier(AccelStructBarrier{tlas.value(), ResourceState::AccelStructWrite, ResourceState::AccelStructRead});
        recordClear(cmd, out);
        cmd.setRayTracingState(so.value(), table.value());
        cmd.setBindingSet(0, set.value());
        cmd.setPushConstants(grid, sizeof(grid));
        cmd.dispatchRays(kWidth, kHeight);
        recordReadback(cmd, out, readback, outBytes);
    }));
    auto got = readBack<uint32_t>(dev(), readback, kWidth * kHeight);
    ASSERT_EQ(got.size(), size_t(kWidth) * kHeight);
    uint32_t wrong = 0;
    uint32_t seen[5] = {};
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) {
            const float px = grid[0] + (float(x) + 0.5f) * grid[4];
            const int quadIndex = int(std::floor(px / kQuadSpacing));
            const bool onQuad = px >= 0 && quadIndex < 4 && px - kQuadSpacing * float(quadIndex) <= 1.0f;
            uint32_t want = kRayGenBase + kMissValue;
            if (onQuad) want = kRayGenBase + (quadIndex % 2 == 0 ? 1000u : 2000u) + kHitValues[quadIndex];
            ++seen[onQuad ? quadIndex : 4];
            if (got[y * kWidth + x] != want && ++wrong <= 10)
                ADD_FAILURE() << "pixel (" << x << ", " << y << "): " << got[y * kWidth + x] << ", want " << want;
        }
    }
    EXPECT_EQ(wrong, 0u);
    for (uint32_t count : seen) EXPECT_GT(count, 0u);   // every record and the miss record were exercised
}

TEST_F(RayTracingTest, ShaderTableRefusesLocalDataLargerThanDeclared) {
    auto so = dev().createStateObject(recordStateObjectDesc(makeLayout(dev(), 0)));
    ASSERT_TRUE(so) << so.message();
    ShaderTableDesc desc{so.value()};
    desc.setRayGen("rayGen").addMiss("miss").addHitGroup("groupA", std::vector<uint8_t>(8, 0));
    auto table = dev().createShaderTable(desc);
    ASSERT_FALSE(table);
    EXPECT_NE(table.message().find("groupA"), std::string::npos) << table.message();
}

TEST_F(RayTracingTest, ShaderTableRefusesUnknownExportName) {
    auto so = dev().createStateObject(recordStateObjectDesc(makeLayout(dev(), 0)));
    ASSERT_TRUE(so) << so.message();
    auto table = dev().createShaderTable(ShaderTableDesc{so.value()}.setRayGen("rayGen").addMiss("noSuchMiss"));
    ASSERT_FALSE(table);
    EXPECT_NE(table.message().find("noSuchMiss"), std::string::npos) << table.message();
}

TEST_F(RayTracingTest, StateObjectErrorNamesHitGroupAndUnknownExport) {
    StateObjectDesc desc = recordStateObjectDesc(makeLayout(dev(), 0));
    desc.hitGroups.push_back({"brokenGroup", HitGroupType::Triangles, "missingClosestHit", "", ""});
    auto so = dev().createStateObject(desc);
    ASSERT_FALSE(so);
    EXPECT_NE(so.message().find("brokenGroup"), std::string::npos) << so.message();
    EXPECT_NE(so.message().find("missingClosestHit"), std::string::npos) << so.message();
}

TEST_F(RayTracingTest, StateObjectRefusesRecursionDepthAboveDeviceLimit) {
    StateObjectDesc desc = recordStateObjectDesc(makeLayout(dev(), 0));
    desc.maxRecursionDepth = dev().capabilities().maxRayRecursionDepth + 1;
    auto so = dev().createStateObject(desc);
    ASSERT_FALSE(so);
    EXPECT_NE(so.message().find("maxRecursionDepth"), std::string::npos) << so.message();
}

TEST_F(RayTracingTest, ShaderIdentifiersHaveHandleSizeAndUnknownNamesAreEmpty) {
    auto so = dev().createStateObject(recordStateObjectDesc(makeLayout(dev(), 0)));
    ASSERT_TRUE(so) << so.message();
    const auto a = so.value()->shaderIdentifier("groupA");
    const auto b = so.value()->shaderIdentifier("groupB");
    EXPECT_EQ(a.size(), dev().capabilities().shaderGroupHandleSize);
    EXPECT_EQ(b.size(), a.size());
    EXPECT_NE(a, b);
    EXPECT_EQ(so.value()->shaderIdentifier("rayGen").size(), a.size());
    EXPECT_TRUE(so.value()->shaderIdentifier("hitA").empty()) << "a closest-hit export is not a group of its own";
    EXPECT_TRUE(so.value()->shaderIdentifier("nothing").empty());
}

}  // namespace
}  // namespace caustics::test
