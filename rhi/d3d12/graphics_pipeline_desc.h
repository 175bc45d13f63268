#pragma once
// rhi::GraphicsPipelineDesc -> D3D12_GRAPHICS_PIPELINE_STATE_DESC, device-free (the device adds the
// root signature and the VS/PS bytecode). Conventions (docs/d3d12.md):
//  - vertex attribute at `location` L is the HLSL semantic ATTRIB<L> (SemanticName "ATTRIB",
//    SemanticIndex L) in input slot `binding`; no attributes = vertex pulling, empty input layout;
//  - strides live in the vertex-buffer views (IASetVertexBuffers), so they are returned per slot;
//  - the HLSL vertex shaders negate clip-space y, so the image and the winding seen by the rasterizer
//    match Vulkan's y-down clip space: FrontCounterClockwise is the RHI flag unchanged;
//  - additiveBlend: ONE + ONE on colour and alpha for every target (dst += src).
#include <array>
#include <string>
#include <vector>

#include "d3d12_headers.h"
#include "caustics/rhi/pipeline.h"
#include "caustics/rhi/result.h"

namespace caustics::rhi::d3d12 {

constexpr const char* kVertexAttributeSemantic = "ATTRIB";
constexpr uint32_t kMaxVertexBufferSlots = D3D12_IA_VERTEX_INPUT_RESOURCE_SLOT_COUNT;   // 32

D3D12_COMPARISON_FUNC toComparisonFunc(CompareOp op);
D3D12_CULL_MODE toCullMode(CullMode mode);
D3D12_PRIMITIVE_TOPOLOGY_TYPE toTopologyType(PrimitiveTopology topology);   // for the PSO
D3D_PRIMITIVE_TOPOLOGY toPrimitiveTopology(PrimitiveTopology topology);      // for IASetPrimitiveTopology

// Fails for attributes without a vertex format, slots out of range, or attributes naming a slot that
// has no VertexBufferLayout.
Result<std::vector<D3D12_INPUT_ELEMENT_DESC>> inputLayoutFromAttributes(const GraphicsPipelineDesc& desc);

// Owns the PSO description and the arrays it points to. Shaders and root signature are left null.
class GraphicsPsoDescStorage {
public:
    static Result<std::unique_ptr<GraphicsPsoDescStorage>> create(const GraphicsPipelineDesc& desc);
    GraphicsPsoDescStorage(const GraphicsPsoDescStorage&) = delete;
    GraphicsPsoDescStorage& operator=(const GraphicsPsoDescStorage&) = delete;

    D3D12_GRAPHICS_PIPELINE_STATE_DESC& desc() { return desc_; }
    const D3D12_GRAPHICS_PIPELINE_STATE_DESC& desc() const { return desc_; }
    // Stride of each vertex-buffer slot (0 = unused), for D3D12_VERTEX_BUFFER_VIEW::StrideInBytes.
    const std::array<uint32_t, kMaxVertexBufferSlots>& strides() const { return strides_; }

private:
    GraphicsPsoDescStorage() = default;
    std::vector<D3D12_INPUT_ELEMENT_DESC> inputElements_;
    std::array<uint32_t, kMaxVertexBufferSlots> strides_{};
    D3D12_GRAPHICS_PIPELINE_STATE_DESC desc_{};
};

}  // namespace caustics::rhi::d3d12
