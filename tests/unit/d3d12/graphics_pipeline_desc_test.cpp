#include <gtest/gtest.h>

#include <string>

#include "graphics_pipeline_desc.h"

namespace caustics::rhi::d3d12 {
namespace {

GraphicsPipelineDesc gbufferLike() {
    GraphicsPipelineDesc d;
    d.colorFormats = {Format::RGBA16_FLOAT, Format::RGBA8_UNORM, Format::R32_UINT};
    d.depthFormat = Format::D32_FLOAT;
    d.cullMode = CullMode::Back;
    d.debugName = "gbuffer";
    return d;
}

TEST(D3D12GraphicsPso, VertexPullingHasAnEmptyInputLayout) {
    auto s = GraphicsPsoDescStorage::create(gbufferLike());
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_EQ(s.value()->desc().InputLayout.NumElements, 0u);
    EXPECT_EQ(s.value()->desc().InputLayout.pInputElementDescs, nullptr);
}

TEST(D3D12GraphicsPso, AttributesBecomeAttribSemanticsIndexedByLocation) {
    GraphicsPipelineDesc d = gbufferLike();
    d.vertexBuffers = {{0, 12}, {1, 32}};
    d.vertexAttributes = {{0, 0, Format::RGB32_FLOAT, 0}, {3, 1, Format::RG32_FLOAT, 16}};
    auto s = GraphicsPsoDescStorage::create(d);
    ASSERT_TRUE(s.ok()) << s.message();
    const D3D12_INPUT_LAYOUT_DESC& il = s.value()->desc().InputLayout;
    ASSERT_EQ(il.NumElements, 2u);
    EXPECT_EQ(std::string(il.pInputElementDescs[1].SemanticName), "ATTRIB");
    EXPECT_EQ(il.pInputElementDescs[1].SemanticIndex, 3u);
    EXPECT_EQ(il.pInputElementDescs[1].InputSlot, 1u);
    EXPECT_EQ(il.pInputElementDescs[1].AlignedByteOffset, 16u);
    EXPECT_EQ(il.pInputElementDescs[1].Format, DXGI_FORMAT_R32G32_FLOAT);
    EXPECT_EQ(il.pInputElementDescs[0].Format, DXGI_FORMAT_R32G32B32_FLOAT);
    EXPECT_EQ(s.value()->strides()[1], 32u);   // strides go to the vertex-buffer views
}

TEST(D3D12GraphicsPso, AttributeOnASlotWithoutLayoutIsRefused) {
    GraphicsPipelineDesc d = gbufferLike();
    d.vertexAttributes = {{0, 2, Format::RGB32_FLOAT, 0}};
    EXPECT_FALSE(GraphicsPsoDescStorage::create(d).ok());
}

TEST(D3D12GraphicsPso, TargetsAndDepthFormatsAreTheViewFormats) {
    auto s = GraphicsPsoDescStorage::create(gbufferLike());
    ASSERT_TRUE(s.ok());
    const auto& d = s.value()->desc();
    ASSERT_EQ(d.NumRenderTargets, 3u);
    EXPECT_EQ(d.RTVFormats[0], DXGI_FORMAT_R16G16B16A16_FLOAT);
    EXPECT_EQ(d.RTVFormats[2], DXGI_FORMAT_R32_UINT);
    EXPECT_EQ(d.DSVFormat, DXGI_FORMAT_D32_FLOAT);   // typed, though the resource is R32_TYPELESS
    EXPECT_EQ(d.SampleDesc.Count, 1u);
    EXPECT_EQ(d.SampleMask, UINT_MAX);
}

TEST(D3D12GraphicsPso, DepthStateFollowsTheDesc) {
    GraphicsPipelineDesc d = gbufferLike();
    d.depthWrite = false;
    d.depthCompare = CompareOp::LessOrEqual;
    auto s = GraphicsPsoDescStorage::create(d);
    ASSERT_TRUE(s.ok());
    const auto& ds = s.value()->desc().DepthStencilState;
    EXPECT_TRUE(ds.DepthEnable);
    EXPECT_EQ(ds.DepthWriteMask, D3D12_DEPTH_WRITE_MASK_ZERO);
    EXPECT_EQ(ds.DepthFunc, D3D12_COMPARISON_FUNC_LESS_EQUAL);
}

TEST(D3D12GraphicsPso, DepthWriteWithoutTestPassesAlways) {
    GraphicsPipelineDesc d = gbufferLike();
    d.depthTest = false;
    auto s = GraphicsPsoDescStorage::create(d);
    ASSERT_TRUE(s.ok());
    EXPECT_TRUE(s.value()->desc().DepthStencilState.DepthEnable);
    EXPECT_EQ(s.value()->desc().DepthStencilState.DepthFunc, D3D12_COMPARISON_FUNC_ALWAYS);
}

TEST(D3D12GraphicsPso, NoDepthFormatLeavesDepthOff) {
    GraphicsPipelineDesc d = gbufferLike();
    d.depthFormat = Format::Unknown;
    auto s = GraphicsPsoDescStorage::create(d);
    ASSERT_TRUE(s.ok());
    EXPECT_FALSE(s.value()->desc().DepthStencilState.DepthEnable);
    EXPECT_EQ(s.value()->desc().DSVFormat, DXGI_FORMAT_UNKNOWN);
}

TEST(D3D12GraphicsPso, CullAndWindingAreTheRhiFlags) {
    GraphicsPipelineDesc d = gbufferLike();
    d.frontCounterClockwise = false;
    auto s = GraphicsPsoDescStorage::create(d);
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(s.value()->desc().RasterizerState.CullMode, D3D12_CULL_MODE_BACK);
    EXPECT_FALSE(s.value()->desc().RasterizerState.FrontCounterClockwise);
    EXPECT_TRUE(s.value()->desc().RasterizerState.DepthClipEnable);
}

TEST(D3D12GraphicsPso, AdditiveBlendIsOnePlusOneOnFloatTargetsOnly) {
    GraphicsPipelineDesc d = gbufferLike();
    d.additiveBlend = true;
    auto s = GraphicsPsoDescStorage::create(d);
    ASSERT_TRUE(s.ok());
    const auto& rt = s.value()->desc().BlendState.RenderTarget;
    EXPECT_TRUE(rt[0].BlendEnable);
    EXPECT_EQ(rt[0].SrcBlend, D3D12_BLEND_ONE);
    EXPECT_EQ(rt[0].DestBlend, D3D12_BLEND_ONE);
    EXPECT_EQ(rt[0].BlendOp, D3D12_BLEND_OP_ADD);
    EXPECT_FALSE(rt[2].BlendEnable);   // R32_UINT: blending is undefined on integer targets
}

TEST(D3D12GraphicsPso, DepthFormatAsColourTargetIsRefused) {
    GraphicsPipelineDesc d = gbufferLike();
    d.colorFormats = {Format::D32_FLOAT};
    EXPECT_FALSE(GraphicsPsoDescStorage::create(d).ok());
}

TEST(D3D12GraphicsPso, TopologyMapsToTypeAndListTopology) {
    EXPECT_EQ(toTopologyType(PrimitiveTopology::TriangleStrip), D3D12_PRIMITIVE_TOPOLOGY_TYPE_TRIANGLE);
    EXPECT_EQ(toPrimitiveTopology(PrimitiveTopology::TriangleStrip), D3D_PRIMITIVE_TOPOLOGY_TRIANGLESTRIP);
    EXPECT_EQ(toTopologyType(PrimitiveTopology::LineList), D3D12_PRIMITIVE_TOPOLOGY_TYPE_LINE);
    EXPECT_EQ(toPrimitiveTopology(PrimitiveTopology::PointList), D3D_PRIMITIVE_TOPOLOGY_POINTLIST);
}

}  // namespace
}  // namespace caustics::rhi::d3d12
