// State-object translation for the two ray-tracing shapes of the caustics module: the forward trace
// (raygen + miss + triangle hit group with closest-hit and any-hit) and the backward sphere pass
// (procedural hit group with intersection + any-hit).
#include <gtest/gtest.h>

#include <string>

#include "state_object_builder.h"

namespace caustics::rhi::d3d12 {
namespace {

// Fake non-null root signatures: the builder only stores the pointers.
ID3D12RootSignature* fakeRootSignature(uintptr_t n) { return reinterpret_cast<ID3D12RootSignature*>(n * 16); }

std::string narrow(const wchar_t* s) { return s ? std::string(s, s + std::wcslen(s)) : std::string(); }

StateObjectDesc forwardTraceDesc() {
    StateObjectDesc d;
    d.debugName = "forward_trace";
    ShaderLibraryDesc lib;
    lib.code.kind = ShaderCodeKind::DXIL;
    lib.exports = {{"RayGen", "forwardRayGen", ShaderStage::RayGen},
                   {"Miss", "Miss", ShaderStage::Miss},
                   {"ClosestHit", "", ShaderStage::ClosestHit},
                   {"AnyHit", "alphaTest", ShaderStage::AnyHit}};
    d.libraries.push_back(lib);
    d.hitGroups.push_back({"TriangleHit", HitGroupType::Triangles, "ClosestHit", "AnyHit", ""});
    d.maxPayloadBytes = 48;
    d.maxAttributeBytes = 8;
    d.maxRecursionDepth = 1;
    d.localBindings.localDataBytes = 16;
    return d;
}

StateObjectDesc backwardSphereDesc() {
    StateObjectDesc d;
    d.debugName = "backward_spheres";
    ShaderLibraryDesc lib;
    lib.code.kind = ShaderCodeKind::DXIL;
    lib.exports = {{"GatherRayGen", "main", ShaderStage::RayGen},
                   {"SphereIntersection", "sphereIntersect", ShaderStage::Intersection},
                   {"SphereAnyHit", "accumulate", ShaderStage::AnyHit}};
    d.libraries.push_back(lib);
    d.hitGroups.push_back({"SphereHit", HitGroupType::Procedural, "", "SphereAnyHit", "SphereIntersection"});
    d.maxPayloadBytes = 16;
    d.maxAttributeBytes = 16;
    d.maxRecursionDepth = 2;
    return d;
}

class StateObjectBuilderTest : public ::testing::Test {
protected:
    Status build(const StateObjectDesc& d) {
        inputs.libraryBytecode.assign(d.libraries.size(), std::span<const uint8_t>(dxil));
        inputs.globalRootSignature = fakeRootSignature(1);
        inputs.localRootSignature = fakeRootSignature(2);
        return builder.build(d, inputs);
    }
    std::vector<uint8_t> dxil = std::vector<uint8_t>(64, 0xAB);
    StateObjectInputs inputs;
    StateObjectBuilder builder;
};

TEST_F(StateObjectBuilderTest, ForwardTraceSubobjectsComeInDocumentedOrder) {
    ASSERT_TRUE(build(forwardTraceDesc()).ok());
    std::vector<D3D12_STATE_SUBOBJECT_TYPE> types;
    for (const auto& s : builder.subobjects()) types.push_back(s.Type);
    const std::vector<D3D12_STATE_SUBOBJECT_TYPE> expected = {
        D3D12_STATE_SUBOBJECT_TYPE_DXIL_LIBRARY, D3D12_STATE_SUBOBJECT_TYPE_HIT_GROUP,
        D3D12_STATE_SUBOBJECT_TYPE_RAYTRACING_SHADER_CONFIG, D3D12_STATE_SUBOBJECT_TYPE_LOCAL_ROOT_SIGNATURE,
        D3D12_STATE_SUBOBJECT_TYPE_SUBOBJECT_TO_EXPORTS_ASSOCIATION, D3D12_STATE_SUBOBJECT_TYPE_GLOBAL_ROOT_SIGNATURE,
        D3D12_STATE_SUBOBJECT_TYPE_RAYTRACING_PIPELINE_CONFIG};
    EXPECT_EQ(types, expected);
    EXPECT_EQ(builder.desc().Type, D3D12_STATE_OBJECT_TYPE_RAYTRACING_PIPELINE);
    EXPECT_EQ(builder.desc().NumSubobjects, expected.size());
    EXPECT_EQ(builder.desc().pSubobjects, builder.subobjects().data());
}

TEST_F(StateObjectBuilderTest, LibraryExportsRenameEntryPointsOnlyWhenTheyDiffer) {
    ASSERT_TRUE(build(forwardTraceDesc()).ok());
    const auto* lib = static_cast<const D3D12_DXIL_LIBRARY_DESC*>(builder.subobjects()[0].pDesc);
    EXPECT_EQ(lib->DXILLibrary.BytecodeLength, dxil.size());
    EXPECT_EQ(lib->DXILLibrary.pShaderBytecode, dxil.data());
    ASSERT_EQ(lib->NumExports, 4u);
    EXPECT_EQ(narrow(lib->pExports[0].Name), "RayGen");
    EXPECT_EQ(narrow(lib->pExports[0].ExportToRename), "forwardRayGen");
    EXPECT_EQ(lib->pExports[1].ExportToRename, nullptr);   // "Miss" is its own entry point
    EXPECT_EQ(lib->pExports[2].ExportToRename, nullptr);   // empty entry point = the export name
    EXPECT_EQ(narrow(lib->pExports[3].ExportToRename), "alphaTest");
}

TEST_F(StateObjectBuilderTest, TriangleHitGroupImportsClosestAndAnyHit) {
    ASSERT_TRUE(build(forwardTraceDesc()).ok());
    const auto* hg = static_cast<const D3D12_HIT_GROUP_DESC*>(builder.subobjects()[1].pDesc);
    EXPECT_EQ(hg->Type, D3D12_HIT_GROUP_TYPE_TRIANGLES);
    EXPECT_EQ(narrow(hg->HitGroupExport), "TriangleHit");
    EXPECT_EQ(narrow(hg->ClosestHitShaderImport), "ClosestHit");
    EXPECT_EQ(narrow(hg->AnyHitShaderImport), "AnyHit");
    EXPECT_EQ(hg->IntersectionShaderImport, nullptr);
}

TEST_F(StateObjectBuilderTest, ShaderConfigCarriesPayloadAndAttributeSizes) {
    ASSERT_TRUE(build(forwardTraceDesc()).ok());
    const auto* cfg = static_cast<const D3D12_RAYTRACING_SHADER_CONFIG*>(builder.subobjects()[2].pDesc);
    EXPECT_EQ(cfg->MaxPayloadSizeInBytes, 48u);
    EXPECT_EQ(cfg->MaxAttributeSizeInBytes, 8u);
}

TEST_F(StateObjectBuilderTest, LocalRootSignatureIsAssociatedWithRayGenMissAndHitGroups) {
    ASSERT_TRUE(build(forwardTraceDesc()).ok());
    const auto subs = builder.subobjects();
    const auto* local = static_cast<const D3D12_LOCAL_ROOT_SIGNATURE*>(subs[3].pDesc);
    EXPECT_EQ(local->pLocalRootSignature, fakeRootSignature(2));
    const auto* assoc = static_cast<const D3D12_SUBOBJECT_TO_EXPORTS_ASSOCIATION*>(subs[4].pDesc);
    EXPECT_EQ(assoc->pSubobjectToAssociate, &subs[3]);
    std::vector<std::string> names;
    for (UINT i = 0; i < assoc->NumExports; ++i) names.push_back(narrow(assoc->pExports[i]));
    EXPECT_EQ(names, (std::vector<std::string>{"RayGen", "Miss", "TriangleHit"}));
}

TEST_F(StateObjectBuilderTest, GlobalRootSignatureAndRecursionDepthAreLast) {
    ASSERT_TRUE(build(forwardTraceDesc()).ok());
    const auto subs = builder.subobjects();
    const auto* global = static_cast<const D3D12_GLOBAL_ROOT_SIGNATURE*>(subs[5].pDesc);
    EXPECT_EQ(global->pGlobalRootSignature, fakeRootSignature(1));
    const auto* pipe = static_cast<const D3D12_RAYTRACING_PIPELINE_CONFIG*>(subs[6].pDesc);
    EXPECT_EQ(pipe->MaxTraceRecursionDepth, 1u);
}

TEST_F(StateObjectBuilderTest, ProceduralSphereHitGroupImportsIntersectionAndAnyHitWithoutClosestHit) {
    ASSERT_TRUE(build(backwardSphereDesc()).ok());
    const auto subs = builder.subobjects();
    ASSERT_EQ(subs.size(), 5u);   // no local data: no local root signature nor association
    EXPECT_EQ(subs[1].Type, D3D12_STATE_SUBOBJECT_TYPE_HIT_GROUP);
    const auto* hg = static_cast<const D3D12_HIT_GROUP_DESC*>(subs[1].pDesc);
    EXPECT_EQ(hg->Type, D3D12_HIT_GROUP_TYPE_PROCEDURAL_PRIMITIVE);
    EXPECT_EQ(narrow(hg->IntersectionShaderImport), "SphereIntersection");
    EXPECT_EQ(narrow(hg->AnyHitShaderImport), "SphereAnyHit");
    EXPECT_EQ(hg->ClosestHitShaderImport, nullptr);
    const auto* cfg = static_cast<const D3D12_RAYTRACING_SHADER_CONFIG*>(subs[2].pDesc);
    EXPECT_EQ(cfg->MaxAttributeSizeInBytes, 16u);
    EXPECT_EQ(static_cast<const D3D12_RAYTRACING_PIPELINE_CONFIG*>(subs[4].pDesc)->MaxTraceRecursionDepth, 2u);
    EXPECT_EQ(builder.shaderTableNames(), (std::vector<std::string>{"GatherRayGen", "SphereHit"}));
}

TEST_F(StateObjectBuilderTest, ProceduralHitGroupWithoutIntersectionIsRefused) {
    StateObjectDesc d = backwardSphereDesc();
    d.hitGroups[0].intersection.clear();
    Status s = build(d);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.message().find("SphereHit"), std::string::npos);
}

TEST_F(StateObjectBuilderTest, HitGroupImportOfWrongStageIsRefused) {
    StateObjectDesc d = forwardTraceDesc();
    d.hitGroups[0].anyHit = "ClosestHit";
    EXPECT_FALSE(build(d).ok());
}

TEST_F(StateObjectBuilderTest, UnknownImportIsRefusedWithItsName) {
    StateObjectDesc d = forwardTraceDesc();
    d.hitGroups[0].closestHit = "Nope";
    Status s = build(d);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.message().find("Nope"), std::string::npos);
}

TEST_F(StateObjectBuilderTest, AttributesLargerThanDxrLimitAreRefused) {
    StateObjectDesc d = backwardSphereDesc();
    d.maxAttributeBytes = 36;   // D3D12_RAYTRACING_MAX_ATTRIBUTE_SIZE_IN_BYTES is 32
    EXPECT_FALSE(build(d).ok());
}

}  // namespace
}  // namespace caustics::rhi::d3d12
