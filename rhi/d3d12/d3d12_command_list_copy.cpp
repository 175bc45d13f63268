// Texture transfers and clears on the command list. Both directions go through placed footprints
// with 256-byte row pitches (texture_copy_layout.h); the RHI's tightly packed rows are repacked on
// the CPU for uploads and by row-wise CopyBufferRegion from a pitched staging buffer for downloads.
// Clears pick a method per texture (texture_clear.h); the RHI leaves the texture in CopyDest.
#include "d3d12_command_list.h"
#include "format_translation.h"
#include "texture_clear.h"
#include "texture_copy_layout.h"

namespace caustics::rhi::d3d12 {
namespace {

D3D12_TEXTURE_COPY_LOCATION subresourceLocation(ID3D12Resource* texture, uint32_t subresource) {
    D3D12_TEXTURE_COPY_LOCATION l{};
    l.pResource = texture;
    l.Type = D3D12_TEXTURE_COPY_TYPE_SUBRESOURCE_INDEX;
    l.SubresourceIndex = subresource;
    return l;
}

D3D12_TEXTURE_COPY_LOCATION footprintLocation(ID3D12Resource* buffer, uint64_t offset, const TextureDesc& desc,
                                              const TextureCopyLayout& layout) {
    D3D12_TEXTURE_COPY_LOCATION l{};
    l.pResource = buffer;
    l.Type = D3D12_TEXTURE_COPY_TYPE_PLACED_FOOTPRINT;
    l.PlacedFootprint.Offset = offset;
    // The resource format (typeless for depth), as GetCopyableFootprints reports it.
    l.PlacedFootprint.Footprint = {toDxgiResourceFormat(desc.format), layout.width, layout.height, 1,
                                   UINT(layout.rowPitch)};
    return l;
}

}  // namespace

void CommandList::copyPixelsToTexture(Texture& t, uint32_t layer, uint32_t mip, const uint8_t* tight, uint64_t bytes) {
    auto layout = textureCopyLayout(t.desc_, layer, mip);
    if (!layout) return fail(layout.error());
    if (bytes < layout->tightBytes)
        return fail(makeError("d3d12 writeTexture: '" + t.desc_.debugName + "' needs " +
                              std::to_string(layout->tightBytes) + " bytes, got " + std::to_string(bytes)));
    const TextureCopyLayout l = layout.value();
    auto staging = uploadWith(l.stagingBytes, [&](uint8_t* mapped) {
        packRowsToPitch(l, {tight, size_t(l.tightBytes)}, {mapped, size_t(l.stagingBytes)});
    });
    if (!staging) return;
    const D3D12_TEXTURE_COPY_LOCATION dst = subresourceLocation(t.resource.get(), l.subresource);
    const D3D12_TEXTURE_COPY_LOCATION src = footprintLocation(staging.get(), 0, t.desc_, l);
    list->CopyTextureRegion(&dst, 0, 0, 0, &src, nullptr);
}

void CommandList::writeTexture(const TextureHandle& dst, uint32_t layer, uint32_t mip, const void* data, uint64_t bytes) {
    copyPixelsToTexture(*static_cast<Texture*>(dst.get()), layer, mip, static_cast<const uint8_t*>(data), bytes);
}

void CommandList::copyTextureToBuffer(const BufferHandle& dstHandle, uint64_t dstOffset, const TextureHandle& srcHandle,
                                      uint32_t layer, uint32_t mip) {
    auto* t = static_cast<Texture*>(srcHandle.get());
    auto* b = static_cast<Buffer*>(dstHandle.get());
    auto layout = textureCopyLayout(t->desc_, layer, mip);
    if (!layout) return fail(layout.error());
    const TextureCopyLayout& l = layout.value();
    if (dstOffset + l.tightBytes > b->desc_.byteSize)
        return fail(makeError("d3d12 copyTextureToBuffer: '" + b->desc_.debugName + "' is too small for '" +
                              t->desc_.debugName + "'"));
    const D3D12_TEXTURE_COPY_LOCATION src = subresourceLocation(t->resource.get(), l.subresource);
    if (copyNeedsNoRepack(l, dstOffset)) {   // tight rows already 256-aligned: straight into the buffer
        const D3D12_TEXTURE_COPY_LOCATION dst = footprintLocation(b->resource.get(), dstOffset, t->desc_, l);
        list->CopyTextureRegion(&dst, 0, 0, 0, &src, nullptr);
        return;
    }
    // Pitched staging on the GPU, then one CopyBufferRegion per row into the tight destination.
    auto staging = createCommittedBuffer(device->d3d(), l.stagingBytes, D3D12_HEAP_TYPE_DEFAULT,
                                         D3D12_RESOURCE_FLAG_NONE, D3D12_RESOURCE_STATE_COPY_DEST, "texture readback staging");
    if (!staging) return fail(staging.error());
    keep(staging.value());
    const D3D12_TEXTURE_COPY_LOCATION dst = footprintLocation(staging.value().get(), 0, t->desc_, l);
    list->CopyTextureRegion(&dst, 0, 0, 0, &src, nullptr);
    D3D12_RESOURCE_BARRIER barrier{};
    barrier.Type = D3D12_RESOURCE_BARRIER_TYPE_TRANSITION;
    barrier.Transition = {staging.value().get(), D3D12_RESOURCE_BARRIER_ALL_SUBRESOURCES,
                          D3D12_RESOURCE_STATE_COPY_DEST, D3D12_RESOURCE_STATE_COPY_SOURCE};
    list->ResourceBarrier(1, &barrier);
    for (uint32_t row = 0; row < l.height; ++row)
        list->CopyBufferRegion(b->resource.get(), dstOffset + row * l.tightRowBytes, staging.value().get(),
                               row * l.rowPitch, l.tightRowBytes);
}

void CommandList::transition(Texture& t, D3D12_RESOURCE_STATES after) {
    if (t.state == after) return;
    D3D12_RESOURCE_BARRIER b{};
    b.Type = D3D12_RESOURCE_BARRIER_TYPE_TRANSITION;
    b.Transition = {t.resource.get(), D3D12_RESOURCE_BARRIER_ALL_SUBRESOURCES, t.state, after};
    list->ResourceBarrier(1, &b);
    t.state = after;
}

void CommandList::clearByCopy(Texture& t, const std::vector<uint8_t>& pixel) {
    for (uint32_t mip = 0; mip < t.desc_.mipLevels; ++mip) {
        auto layout = textureCopyLayout(t.desc_, 0, mip);
        if (!layout) return fail(layout.error());
        std::vector<uint8_t> image(layout->tightBytes);
        for (size_t i = 0; i + pixel.size() <= image.size(); i += pixel.size())
            std::memcpy(image.data() + i, pixel.data(), pixel.size());
        for (uint32_t layer = 0; layer < t.desc_.arrayLayers; ++layer)
            copyPixelsToTexture(t, layer, mip, image.data(), image.size());
    }
}

void CommandList::clearTexture(Texture& t, const float* floats, const uint32_t* uints) {
    const TextureDesc& d = t.desc_;
    const D3D12_RESOURCE_STATES copyDest = D3D12_RESOURCE_STATE_COPY_DEST;
    switch (chooseClearMethod(d, uints != nullptr)) {
        case ClearMethod::UavFloat:
        case ClearMethod::UavUint: {
            auto cpu = nextCpuDescriptor(*uavCpuHeap, uavCpuRange, uavCpuUsed, "clear UAV");
            if (!cpu) return fail(cpu.error());
            D3D12_UNORDERED_ACCESS_VIEW_DESC v{};
            v.Format = toDxgiFormat(d.format);
            if (d.arrayLayers > 1) {
                v.ViewDimension = D3D12_UAV_DIMENSION_TEXTURE2DARRAY;
                v.Texture2DArray.ArraySize = d.arrayLayers;
            } else {
                v.ViewDimension = D3D12_UAV_DIMENSION_TEXTURE2D;
            }
            device->d3d()->CreateUnorderedAccessView(t.resource.get(), nullptr, &v, cpu.value());
            // ClearUnorderedAccessView* wants the same view twice: in a shader-visible heap (GPU
            // handle) and in a CPU-only heap (D3D12 docs, ClearUnorderedAccessViewFloat).
            auto gpu = resourceRing->push(device->d3d(), cpu.value(), 1);
            if (!gpu) return fail(gpu.error());
            transition(t, D3D12_RESOURCE_STATE_UNORDERED_ACCESS);
            if (uints) list->ClearUnorderedAccessViewUint(gpu.value(), cpu.value(), t.resource.get(), uints, 0, nullptr);
            else list->ClearUnorderedAccessViewFloat(gpu.value(), cpu.value(), t.resource.get(), floats, 0, nullptr);
            transition(t, copyDest);
            return;
        }
        case ClearMethod::RenderTarget: {
            transition(t, D3D12_RESOURCE_STATE_RENDER_TARGET);
            for (uint32_t layer = 0; layer < d.arrayLayers; ++layer) {
                for (uint32_t mip = 0; mip < d.mipLevels; ++mip) {
                    auto rtv = nextCpuDescriptor(*rtvHeap, rtvRange, rtvUsed, "render-target");
                    if (!rtv) return fail(rtv.error());
                    D3D12_RENDER_TARGET_VIEW_DESC v{};
                    v.Format = toDxgiFormat(d.format);
                    v.ViewDimension = D3D12_RTV_DIMENSION_TEXTURE2DARRAY;
                    v.Texture2DArray = {mip, layer, 1, 0};
                    device->d3d()->CreateRenderTargetView(t.resource.get(), &v, rtv.value());
                    list->ClearRenderTargetView(rtv.value(), floats, 0, nullptr);
                }
            }
            transition(t, copyDest);
            return;
        }
        case ClearMethod::DepthStencil: {
            transition(t, D3D12_RESOURCE_STATE_DEPTH_WRITE);
            for (uint32_t layer = 0; layer < d.arrayLayers; ++layer) {
                auto dsv = nextCpuDescriptor(*dsvHeap, dsvRange, dsvUsed, "depth-stencil");
                if (!dsv) return fail(dsv.error());
                D3D12_DEPTH_STENCIL_VIEW_DESC v{};
                v.Format = toDxgiDsvFormat(d.format);
                v.ViewDimension = D3D12_DSV_DIMENSION_TEXTURE2DARRAY;
                v.Texture2DArray = {0, layer, 1};
                device->d3d()->CreateDepthStencilView(t.resource.get(), &v, dsv.value());
                const bool stencil = formatInfo(d.format).hasStencil;
                list->ClearDepthStencilView(dsv.value(), stencil ? D3D12_CLEAR_FLAG_DEPTH | D3D12_CLEAR_FLAG_STENCIL
                                                                 : D3D12_CLEAR_FLAG_DEPTH,
                                            floats[0], 0, 0, nullptr);
            }
            transition(t, copyDest);
            return;
        }
        case ClearMethod::Copy:
            clearByCopy(t, uints ? encodeClearPixel(d.format, uints) : encodeClearPixel(d.format, floats));
            return;
    }
}

void CommandList::clearTextureFloat(const TextureHandle& texture, const float value[4]) {
    clearTexture(*static_cast<Texture*>(texture.get()), value, nullptr);
}

void CommandList::clearTextureUint(const TextureHandle& texture, const uint32_t value[4]) {
    clearTexture(*static_cast<Texture*>(texture.get()), nullptr, value);
}

}  // namespace caustics::rhi::d3d12
