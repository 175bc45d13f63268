#include <gtest/gtest.h>

#include "shader_table_image.h"

namespace caustics::rhi::d3d12 {
namespace {

// A fake identifier whose 32 bytes all equal a per-name tag, so records can be recognised.
std::vector<uint8_t> identifierOf(const std::string& name) {
    static const std::vector<std::string> known = {"RayGen", "Miss", "ShadowMiss", "TriangleHit", "SphereHit"};
    for (size_t i = 0; i < known.size(); ++i)
        if (known[i] == name) return std::vector<uint8_t>(32, uint8_t(i + 1));
    return {};
}

ShaderTableDesc forwardTable() {
    ShaderTableDesc d;
    d.setRayGen("RayGen").addMiss("Miss").addMiss("ShadowMiss").addHitGroup("TriangleHit", {1, 2, 3, 4});
    return d;
}

TEST(D3D12ShaderTable, AlignmentIsD3D12s32And64) {
    const ShaderTableAlignment a = d3d12ShaderTableAlignment();
    EXPECT_EQ(a.handleSize, 32u);
    EXPECT_EQ(a.handleAlignment, 32u);
    EXPECT_EQ(a.baseAlignment, 64u);
    EXPECT_EQ(a.maxStride, 4096u);
}

TEST(D3D12ShaderTable, RecordStridesAreMultiplesOf32AndRegionsStartAtMultiplesOf64) {
    auto image = buildShaderTableImage(forwardTable(), 16, identifierOf);
    ASSERT_TRUE(image.ok()) << image.message();
    const ShaderTableLayout& l = image->layout;
    for (const ShaderTableRegion* r : {&l.rayGen, &l.miss, &l.hitGroup}) {
        EXPECT_EQ(r->stride % 32, 0u);
        EXPECT_EQ(r->offset % 64, 0u);
    }
    EXPECT_EQ(l.hitGroup.stride, 64u);   // 32-byte identifier + 16 bytes of local data, rounded up to 32
    EXPECT_EQ(l.miss.size, 2 * l.miss.stride);
    EXPECT_EQ(image->bytes.size(), l.totalBytes);
    EXPECT_EQ(l.totalBytes % 64, 0u);
}

TEST(D3D12ShaderTable, RecordsStartWithTheIdentifierFollowedByLocalData) {
    auto image = buildShaderTableImage(forwardTable(), 16, identifierOf);
    ASSERT_TRUE(image.ok());
    const auto& b = image->bytes;
    const ShaderTableLayout& l = image->layout;
    EXPECT_EQ(b[l.rayGen.offset], 1);
    EXPECT_EQ(b[l.miss.offset + l.miss.stride], 3);        // second miss record: ShadowMiss
    EXPECT_EQ(b[l.hitGroup.offset + 31], 4);
    EXPECT_EQ(b[l.hitGroup.offset + 32], 1);               // local data right after the identifier
    EXPECT_EQ(b[l.hitGroup.offset + 35], 4);
}

TEST(D3D12ShaderTable, UnknownExportIsRefusedWithItsName) {
    ShaderTableDesc d = forwardTable();
    d.addHitGroup("Missing");
    auto image = buildShaderTableImage(d, 16, identifierOf);
    ASSERT_FALSE(image.ok());
    EXPECT_NE(image.message().find("Missing"), std::string::npos);
}

TEST(D3D12ShaderTable, LocalDataLargerThanTheStateObjectAllowsIsRefused) {
    auto image = buildShaderTableImage(forwardTable(), 0, identifierOf);
    EXPECT_FALSE(image.ok());
}

TEST(D3D12ShaderTable, DispatchRaysRegionsPointIntoTheTable) {
    auto image = buildShaderTableImage(forwardTable(), 16, identifierOf);
    ASSERT_TRUE(image.ok());
    const uint64_t base = 0x10000;
    D3D12_DISPATCH_RAYS_DESC d = makeDispatchRaysDesc(image->layout, base, 512, 512, 3);
    EXPECT_EQ(d.RayGenerationShaderRecord.StartAddress, base);
    EXPECT_EQ(d.RayGenerationShaderRecord.SizeInBytes, image->layout.rayGen.stride);
    EXPECT_EQ(d.MissShaderTable.StartAddress, base + image->layout.miss.offset);
    EXPECT_EQ(d.MissShaderTable.StrideInBytes, image->layout.miss.stride);
    EXPECT_EQ(d.HitGroupTable.SizeInBytes, image->layout.hitGroup.size);
    EXPECT_EQ(d.CallableShaderTable.StartAddress, 0u);   // empty region
    EXPECT_EQ(d.Depth, 3u);   // light index as the third grid dimension
}

}  // namespace
}  // namespace caustics::rhi::d3d12
