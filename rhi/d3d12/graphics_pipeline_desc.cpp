#include "graphics_pipeline_desc.h"

#include "format_translation.h"

namespace caustics::rhi::d3d12 {

D3D12_COMPARISON_FUNC toComparisonFunc(CompareOp op) {
    switch (op) {
        case CompareOp::Never: return D3D12_COMPARISON_FUNC_NEVER;
        case CompareOp::Less: return D3D12_COMPARISON_FUNC_LESS;
        case CompareOp::LessOrEqual: return D3D12_COMPARISON_FUNC_LESS_EQUAL;
        case CompareOp::Equal: return D3D12_COMPARISON_FUNC_EQUAL;
        case CompareOp::Greater: return D3D12_COMPARISON_FUNC_GREATER;
        case CompareOp::GreaterOrEqual: return D3D12_COMPARISON_FUNC_GREATER_EQUAL;
        case CompareOp::Always: return D3D12_COMPARISON_FUNC_ALWAYS;
    }
    return D3D12_COMPARISON_FUNC_ALWAYS;
}

D3D12_CULL_MODE toCullMode(CullMode mode) {
    switch (mode) {
        case CullMode::Front: return D3D12_CULL_MODE_FRONT;
        case CullMode::Back: return D3D12_CULL_MODE_BACK;
        default: return D3D12_CULL_MODE_NONE;
    }
}

D3D12_PRIMITIVE_TOPOLOGY_TYPE toTopologyType(PrimitiveTopology topology) {
    switch (topology) {
        case PrimitiveTopology::LineList: return D3D12_PRIMITIVE_TOPOLOGY_TYPE_LINE;
        case PrimitiveTopology::PointList: return D3D12_PRIMITIVE_TOPOLOGY_TYPE_POINT;
        default: return D3D12_PRIMITIVE_TOPOLOGY_TYPE_TRIANGLE;
    }
}

D3D_PRIMITIVE_TOPOLOGY toPrimitiveTopology(PrimitiveTopology topology) {
    switch (topology) {
        case PrimitiveTopology::TriangleStrip: return D3D_PRIMITIVE_TOPOLOGY_TRIANGLESTRIP;
        case PrimitiveTopology::LineList: return D3D_PRIMITIVE_TOPOLOGY_LINELIST;
        case PrimitiveTopology::PointList: return D3D_PRIMITIVE_TOPOLOGY_POINTLIST;
        default: return D3D_PRIMITIVE_TOPOLOGY_TRIANGLELIST;
    }
}

Result<std::vector<D3D12_INPUT_ELEMENT_DESC>> inputLayoutFromAttributes(const GraphicsPipelineDesc& desc) {
    std::vector<D3D12_INPUT_ELEMENT_DESC> out;
    for (const VertexAttribute& a : desc.vertexAttributes) {
        const std::string where = "d3d12 pipeline '" + desc.debugName + "': vertex attribute " + std::to_string(a.location);
        const DXGI_FORMAT format = toDxgiFormat(a.format);
        if (format == DXGI_FORMAT_UNKNOWN || formatInfo(a.format).isDepth)
            return makeError(where + " has no vertex format");
        if (a.binding >= kMaxVertexBufferSlots) return makeError(where + " uses slot " + std::to_string(a.binding) + " (max 31)");
        bool slotDeclared = false;
        for (const VertexBufferLayout& b : desc.vertexBuffers) slotDeclared |= b.binding == a.binding;
        if (!slotDeclared) return makeError(where + " reads slot " + std::to_string(a.binding) + ", which has no vertex buffer layout");
        D3D12_INPUT_ELEMENT_DESC e{};
        e.SemanticName = kVertexAttributeSemantic;   // static storage: the pointer outlives the PSO creation
        e.SemanticIndex = a.location;
        e.Format = format;
        e.InputSlot = a.binding;
        e.AlignedByteOffset = a.offset;
        e.InputSlotClass = D3D12_INPUT_CLASSIFICATION_PER_VERTEX_DATA;
        out.push_back(e);
    }
    return out;
}

Result<std::unique_ptr<GraphicsPsoDescStorage>> GraphicsPsoDescStorage::create(const GraphicsPipelineDesc& desc) {
    std::unique_ptr<GraphicsPsoDescStorage> s(new GraphicsPsoDescStorage());
    CAUSTICS_TRY(s->inputElements_, inputLayoutFromAttributes(desc));
    for (const VertexBufferLayout& b : desc.vertexBuffers) {
        if (b.binding >= kMaxVertexBufferSlots)
            return makeError("d3d12 pipeline '" + desc.debugName + "': vertex buffer slot " + std::to_string(b.binding) + " (max 31)");
        s->strides_[b.binding] = b.stride;
    }
    if (desc.colorFormats.size() > D3D12_SIMULTANEOUS_RENDER_TARGET_COUNT)
        return makeError("d3d12 pipeline '" + desc.debugName + "': more than 8 colour targets");

    D3D12_GRAPHICS_PIPELINE_STATE_DESC& d = s->desc_;
    d.InputLayout = {s->inputElements_.empty() ? nullptr : s->inputElements_.data(), UINT(s->inputElements_.size())};
    d.PrimitiveTopologyType = toTopologyType(desc.topology);
    d.SampleMask = UINT_MAX;
    d.SampleDesc.Count = 1;

    d.RasterizerState.FillMode = D3D12_FILL_MODE_SOLID;
    d.RasterizerState.CullMode = toCullMode(desc.cullMode);
    d.RasterizerState.FrontCounterClockwise = desc.frontCounterClockwise ? TRUE : FALSE;
    d.RasterizerState.DepthClipEnable = TRUE;   // Vulkan's default (depthClampEnable = false)

    d.NumRenderTargets = UINT(desc.colorFormats.size());
    for (size_t i = 0; i < desc.colorFormats.size(); ++i) {
        const DXGI_FORMAT f = toDxgiFormat(desc.colorFormats[i]);
        if (f == DXGI_FORMAT_UNKNOWN || formatInfo(desc.colorFormats[i]).isDepth)
            return makeError("d3d12 pipeline '" + desc.debugName + "': colour target " + std::to_string(i) + " has no render-target format");
        d.RTVFormats[i] = f;
        D3D12_RENDER_TARGET_BLEND_DESC& b = d.BlendState.RenderTarget[i];
        b.RenderTargetWriteMask = D3D12_COLOR_WRITE_ENABLE_ALL;
        b.SrcBlend = b.SrcBlendAlpha = D3D12_BLEND_ONE;
        b.DestBlend = b.DestBlendAlpha = desc.additiveBlend ? D3D12_BLEND_ONE : D3D12_BLEND_ZERO;
        b.BlendOp = b.BlendOpAlpha = D3D12_BLEND_OP_ADD;
        b.LogicOp = D3D12_LOGIC_OP_NOOP;
        // Blending is undefined on integer targets (object ids): only float/unorm targets blend.
        b.BlendEnable = desc.additiveBlend && !formatInfo(desc.colorFormats[i]).isInteger ? TRUE : FALSE;
    }
    d.BlendState.IndependentBlendEnable = TRUE;

    if (desc.depthFormat != Format::Unknown) {
        d.DSVFormat = toDxgiDsvFormat(desc.depthFormat);
        if (d.DSVFormat == DXGI_FORMAT_UNKNOWN)
            return makeError("d3d12 pipeline '" + desc.debugName + "': depth format is not a depth format");
        d.DepthStencilState.DepthEnable = desc.depthTest || desc.depthWrite ? TRUE : FALSE;
        d.DepthStencilState.DepthWriteMask = desc.depthWrite ? D3D12_DEPTH_WRITE_MASK_ALL : D3D12_DEPTH_WRITE_MASK_ZERO;
        // Vulkan writes depth with the test off only when compare = ALWAYS; D3D12 needs DepthEnable for
        // writes, so "write without test" becomes ALWAYS.
        d.DepthStencilState.DepthFunc = desc.depthTest ? toComparisonFunc(desc.depthCompare) : D3D12_COMPARISON_FUNC_ALWAYS;
    }
    d.DepthStencilState.StencilEnable = FALSE;
    return s;
}

}  // namespace caustics::rhi::d3d12
