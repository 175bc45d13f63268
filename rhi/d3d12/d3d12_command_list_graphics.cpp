// Rasterization on the command list: render-target / depth views from per-recording CPU heaps,
// clears at beginRendering, viewport + scissor, vertex/index buffers and draws. D3D12 has no render
// passes here (plain OMSetRenderTargets), so endRendering only forgets the targets.
#include "d3d12_command_list.h"
#include "format_translation.h"

namespace caustics::rhi::d3d12 {

Result<D3D12_CPU_DESCRIPTOR_HANDLE> CommandList::nextCpuDescriptor(CpuDescriptorHeap& heap, const DescriptorRange& range,
                                                                   uint32_t& used, const char* what) {
    if (used >= range.count)
        return makeError(std::string("d3d12: more than ") + std::to_string(range.count) + " " + what +
                         " descriptors in one recording");
    return heap.at(range.first + used++);
}

void CommandList::beginRendering(const RenderingDesc& desc) {
    std::array<D3D12_CPU_DESCRIPTOR_HANDLE, D3D12_SIMULTANEOUS_RENDER_TARGET_COUNT> rtvs{};
    if (desc.colors.size() > rtvs.size()) return fail(makeError("d3d12 beginRendering: more than 8 colour targets"));
    for (size_t i = 0; i < desc.colors.size(); ++i) {
        const ColorAttachment& c = desc.colors[i];
        auto* t = static_cast<Texture*>(c.texture.get());
        if (!t) return fail(makeError("d3d12 beginRendering: colour target " + std::to_string(i) + " has no texture"));
        auto handle = nextCpuDescriptor(*rtvHeap, rtvRange, rtvUsed, "render-target");
        if (!handle) return fail(handle.error());
        D3D12_RENDER_TARGET_VIEW_DESC v{};
        v.Format = toDxgiFormat(t->desc_.format);
        if (t->desc_.arrayLayers > 1) {   // one layer of an array (caustic maps: one per light)
            v.ViewDimension = D3D12_RTV_DIMENSION_TEXTURE2DARRAY;
            v.Texture2DArray = {0, c.layer, 1, 0};
        } else {
            v.ViewDimension = D3D12_RTV_DIMENSION_TEXTURE2D;
        }
        device->d3d()->CreateRenderTargetView(t->resource.get(), &v, handle.value());
        rtvs[i] = handle.value();
        if (c.clear) list->ClearRenderTargetView(rtvs[i], c.clearValue, 0, nullptr);
    }
    D3D12_CPU_DESCRIPTOR_HANDLE dsv{};
    auto* depth = static_cast<Texture*>(desc.depth.texture.get());
    if (depth) {
        auto handle = nextCpuDescriptor(*dsvHeap, dsvRange, dsvUsed, "depth-stencil");
        if (!handle) return fail(handle.error());
        D3D12_DEPTH_STENCIL_VIEW_DESC v{};
        v.Format = toDxgiDsvFormat(depth->desc_.format);
        if (depth->desc_.arrayLayers > 1) {
            v.ViewDimension = D3D12_DSV_DIMENSION_TEXTURE2DARRAY;
            v.Texture2DArray = {0, desc.depth.layer, 1};
        } else {
            v.ViewDimension = D3D12_DSV_DIMENSION_TEXTURE2D;
        }
        device->d3d()->CreateDepthStencilView(depth->resource.get(), &v, handle.value());
        dsv = handle.value();
        if (desc.depth.clear) list->ClearDepthStencilView(dsv, D3D12_CLEAR_FLAG_DEPTH, desc.depth.clearDepth, 0, 0, nullptr);
    }
    list->OMSetRenderTargets(UINT(desc.colors.size()), desc.colors.empty() ? nullptr : rtvs.data(), FALSE,
                             depth ? &dsv : nullptr);
    // The whole target by default; setViewport narrows it (Vulkan requires the call, D3D12 does not).
    if (desc.width && desc.height) setViewport(0, 0, float(desc.width), float(desc.height));
}

void CommandList::endRendering() {}

void CommandList::setGraphicsPipeline(const GraphicsPipelineHandle& pipeline) {
    auto* p = static_cast<GraphicsPipeline*>(pipeline.get());
    list->SetGraphicsRootSignature(p->root.rootSignature.get());
    list->SetPipelineState(p->pso.get());
    list->IASetPrimitiveTopology(p->topology);
    root = &p->root;
    computeBindPoint = false;
    graphics = p;
}

void CommandList::setViewport(float x, float y, float width, float height) {
    const D3D12_VIEWPORT viewport{x, y, width, height, 0.0f, 1.0f};
    const D3D12_RECT scissor{LONG(x), LONG(y), LONG(x + width), LONG(y + height)};
    list->RSSetViewports(1, &viewport);
    list->RSSetScissorRects(1, &scissor);
}

void CommandList::setVertexBuffer(uint32_t slot, const BufferHandle& buffer, uint64_t offset) {
    if (slot >= kMaxVertexBufferSlots) return fail(makeError("d3d12 setVertexBuffer: slot " + std::to_string(slot)));
    auto* b = static_cast<Buffer*>(buffer.get());
    // The stride belongs to the pipeline in the RHI but to the view in D3D12: it is filled in at draw
    // time from the pipeline bound then (flushDrawState).
    vertexBuffers[slot] = {b->deviceAddress() + offset, UINT(b->desc_.byteSize - offset), 0};
    vertexBufferSlots = std::max(vertexBufferSlots, slot + 1);
}

void CommandList::setIndexBuffer(const BufferHandle& buffer, uint64_t offset) {
    auto* b = static_cast<Buffer*>(buffer.get());
    const D3D12_INDEX_BUFFER_VIEW view{b->deviceAddress() + offset, UINT(b->desc_.byteSize - offset), DXGI_FORMAT_R32_UINT};
    list->IASetIndexBuffer(&view);
}

bool CommandList::flushDrawState(uint32_t baseVertex, uint32_t firstInstance) {
    if (!graphics) {
        fail(makeError("d3d12 draw: no graphics pipeline set"));
        return false;
    }
    if (vertexBufferSlots > 0) {
        for (uint32_t s = 0; s < vertexBufferSlots; ++s) vertexBuffers[s].StrideInBytes = graphics->strides[s];
        list->IASetVertexBuffers(0, vertexBufferSlots, vertexBuffers.data());
    }
    // gl_InstanceIndex / gl_VertexIndex include the draw's bases; SV_InstanceID does not, so the HLSL
    // adds drawParams.firstInstance (root_signature_layout.h, kDrawParametersSpace).
    if (graphics->root.layout.drawParametersParameter >= 0) {
        const uint32_t values[2] = {baseVertex, firstInstance};
        list->SetGraphicsRoot32BitConstants(UINT(graphics->root.layout.drawParametersParameter), 2, values, 0);
    }
    return true;
}

void CommandList::draw(uint32_t vertexCount, uint32_t instanceCount, uint32_t firstVertex, uint32_t firstInstance) {
    if (flushDrawState(firstVertex, firstInstance)) list->DrawInstanced(vertexCount, instanceCount, firstVertex, firstInstance);
}

void CommandList::drawIndexed(uint32_t indexCount, uint32_t instanceCount, uint32_t firstIndex, int32_t vertexOffset,
                              uint32_t firstInstance) {
    if (flushDrawState(uint32_t(vertexOffset), firstInstance))
        list->DrawIndexedInstanced(indexCount, instanceCount, firstIndex, vertexOffset, firstInstance);
}

}  // namespace caustics::rhi::d3d12
