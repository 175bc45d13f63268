#include <gtest/gtest.h>

#include "root_signature_layout.h"

namespace caustics::rhi::d3d12 {
namespace {

std::vector<BindingLayoutDesc> twoLayouts() {
    BindingLayoutDesc frame, pass;
    frame.add(0, BindingType::ConstantBuffer).add(0, BindingType::Sampler);
    pass.add(0, BindingType::AccelStruct).add(0, BindingType::StorageTexture);
    return {frame, pass};
}

TEST(D3D12RootSignature, PushConstantsAreRootConstantsAtB0Space999First) {
    auto l = rootSignatureLayoutFromBindings(twoLayouts(), 16);
    ASSERT_TRUE(l.ok()) << l.message();
    ASSERT_EQ(l->pushConstantParameter, 0);
    const RootParameterLayout& p = l->parameters[0];
    EXPECT_EQ(p.kind, RootParameterLayout::Kind::Constants);
    EXPECT_EQ(p.shaderRegister, 0u);
    EXPECT_EQ(p.registerSpace, 999u);
    EXPECT_EQ(p.num32BitValues, 4u);
}

TEST(D3D12RootSignature, BindingLayoutIBecomesTablesInRegisterSpaceI) {
    auto l = rootSignatureLayoutFromBindings(twoLayouts(), 16);
    ASSERT_TRUE(l.ok());
    // push constants, layout 0 resources, layout 0 samplers, layout 1 resources
    ASSERT_EQ(l->parameters.size(), 4u);
    EXPECT_EQ(l->resourceTableParameter, (std::vector<int32_t>{1, 3}));
    EXPECT_EQ(l->samplerTableParameter, (std::vector<int32_t>{2, -1}));
    EXPECT_TRUE(l->parameters[2].samplerTable);
    for (const RootDescriptorRange& r : l->parameters[3].ranges) EXPECT_EQ(r.space, 1u);
    EXPECT_EQ(l->parameters[3].ranges[0].registerClass, RegisterClass::Srv);
    EXPECT_EQ(l->parameters[3].ranges[1].registerClass, RegisterClass::Uav);
    EXPECT_EQ(l->parameters[3].ranges[1].tableOffset, 1u);
}

TEST(D3D12RootSignature, NoPushConstantsMeansTablesStartAtParameterZero) {
    auto l = rootSignatureLayoutFromBindings(twoLayouts(), 0);
    ASSERT_TRUE(l.ok());
    EXPECT_EQ(l->pushConstantParameter, -1);
    EXPECT_EQ(l->resourceTableParameter[0], 0);
}

TEST(D3D12RootSignature, PushConstantsOver128BytesAreRefused) {
    EXPECT_FALSE(rootSignatureLayoutFromBindings(twoLayouts(), 132).ok());
}

TEST(D3D12RootSignature, VersionedDescMirrorsTheLayout) {
    auto l = rootSignatureLayoutFromBindings(twoLayouts(), 8, RootSignatureKind::Graphics);
    ASSERT_TRUE(l.ok());
    RootSignatureDescStorage storage(*l);
    const D3D12_VERSIONED_ROOT_SIGNATURE_DESC& d = storage.desc();
    EXPECT_EQ(d.Version, D3D_ROOT_SIGNATURE_VERSION_1_1);
    ASSERT_EQ(d.Desc_1_1.NumParameters, 5u);   // + draw parameters (graphics)
    EXPECT_EQ(d.Desc_1_1.Flags, D3D12_ROOT_SIGNATURE_FLAG_ALLOW_INPUT_ASSEMBLER_INPUT_LAYOUT);
    EXPECT_EQ(d.Desc_1_1.pParameters[0].ParameterType, D3D12_ROOT_PARAMETER_TYPE_32BIT_CONSTANTS);
    EXPECT_EQ(d.Desc_1_1.pParameters[0].Constants.RegisterSpace, 999u);
    const D3D12_ROOT_PARAMETER1& samplers = d.Desc_1_1.pParameters[2];
    ASSERT_EQ(samplers.ParameterType, D3D12_ROOT_PARAMETER_TYPE_DESCRIPTOR_TABLE);
    ASSERT_EQ(samplers.DescriptorTable.NumDescriptorRanges, 1u);
    EXPECT_EQ(samplers.DescriptorTable.pDescriptorRanges[0].RangeType, D3D12_DESCRIPTOR_RANGE_TYPE_SAMPLER);
    const D3D12_ROOT_PARAMETER1& pass = d.Desc_1_1.pParameters[3];
    EXPECT_EQ(pass.DescriptorTable.pDescriptorRanges[1].RangeType, D3D12_DESCRIPTOR_RANGE_TYPE_UAV);
    EXPECT_EQ(pass.DescriptorTable.pDescriptorRanges[1].RegisterSpace, 1u);
    EXPECT_EQ(pass.DescriptorTable.pDescriptorRanges[1].OffsetInDescriptorsFromTableStart, 1u);
}

TEST(D3D12RootSignature, GraphicsSignatureEndsWithDrawParametersInSpace998) {
    auto l = rootSignatureLayoutFromBindings(twoLayouts(), 8, RootSignatureKind::Graphics);
    ASSERT_TRUE(l.ok());
    ASSERT_EQ(l->drawParametersParameter, int32_t(l->parameters.size()) - 1);
    const RootParameterLayout& p = l->parameters.back();
    EXPECT_EQ(p.kind, RootParameterLayout::Kind::Constants);
    EXPECT_EQ(p.registerSpace, 998u);
    EXPECT_EQ(p.shaderRegister, 0u);
    EXPECT_EQ(p.num32BitValues, 2u);
}

TEST(D3D12RootSignature, ComputeSignatureHasNoDrawParameters) {
    auto l = rootSignatureLayoutFromBindings(twoLayouts(), 8, RootSignatureKind::Compute);
    ASSERT_TRUE(l.ok());
    EXPECT_EQ(l->drawParametersParameter, -1);
    EXPECT_EQ(l->parameters.size(), 4u);
}

TEST(D3D12RootSignature, LocalSignatureHoldsLocalDataAsRootConstantsInSpace1000) {
    auto l = localRootSignatureLayout(24);
    ASSERT_TRUE(l.ok());
    RootSignatureDescStorage storage(*l);
    const auto& d = storage.desc().Desc_1_1;
    EXPECT_EQ(d.Flags, D3D12_ROOT_SIGNATURE_FLAG_LOCAL_ROOT_SIGNATURE);
    ASSERT_EQ(d.NumParameters, 1u);
    EXPECT_EQ(d.pParameters[0].Constants.Num32BitValues, 6u);
    EXPECT_EQ(d.pParameters[0].Constants.RegisterSpace, 1000u);
}

TEST(D3D12RootSignature, LocalDataNotAMultipleOf4IsRefused) {
    EXPECT_FALSE(localRootSignatureLayout(6).ok());
}

TEST(D3D12RootSignature, SingleGraphicsStageNarrowsVisibility) {
    EXPECT_EQ(toShaderVisibility(ShaderStage::Fragment), D3D12_SHADER_VISIBILITY_PIXEL);
    EXPECT_EQ(toShaderVisibility(ShaderStage::Vertex), D3D12_SHADER_VISIBILITY_VERTEX);
    EXPECT_EQ(toShaderVisibility(ShaderStage::AllRayTracing), D3D12_SHADER_VISIBILITY_ALL);
}

}  // namespace
}  // namespace caustics::rhi::d3d12
