// Buffers, textures, samplers, heaps (committed or placed), binding layouts and sets.
#include <algorithm>
#include <cstring>

#include "d3d12_device.h"
#include "d3d12_objects.h"
#include "format_translation.h"

namespace caustics::rhi::d3d12 {

void setDebugName(ID3D12Object* object, const std::string& name) {
    if (!object || name.empty()) return;
    std::wstring w(name.begin(), name.end());
    object->SetName(w.c_str());
}

namespace {

D3D12_RESOURCE_DESC bufferResourceDesc(uint64_t bytes, D3D12_RESOURCE_FLAGS flags) {
    D3D12_RESOURCE_DESC d{};
    d.Dimension = D3D12_RESOURCE_DIMENSION_BUFFER;
    d.Width = std::max<uint64_t>(bytes, 1);
    d.Height = d.DepthOrArraySize = d.MipLevels = 1;
    d.SampleDesc.Count = 1;
    d.Layout = D3D12_TEXTURE_LAYOUT_ROW_MAJOR;
    d.Flags = flags;
    return d;
}

D3D12_RESOURCE_DESC bufferDescFor(const BufferDesc& desc) {
    D3D12_RESOURCE_FLAGS flags = D3D12_RESOURCE_FLAG_NONE;
    // Storage buffers are UAVs; AS storage must be UAV-capable too (DXR spec).
    if (desc.memory == MemoryType::DeviceLocal &&
        hasAny(desc.usage, BufferUsage::Storage | BufferUsage::AccelStructStorage))
        flags = D3D12_RESOURCE_FLAG_ALLOW_UNORDERED_ACCESS;
    // Constant-buffer views need 256-byte sizes (D3D12_CONSTANT_BUFFER_DATA_PLACEMENT_ALIGNMENT).
    uint64_t size = hasAny(desc.usage, BufferUsage::Constant) ? alignUp(desc.byteSize, 256) : desc.byteSize;
    return bufferResourceDesc(size, flags);
}

D3D12_RESOURCE_DESC textureDescFor(const TextureDesc& desc) {
    D3D12_RESOURCE_DESC d{};
    d.Dimension = D3D12_RESOURCE_DIMENSION_TEXTURE2D;
    d.Width = desc.width;
    d.Height = desc.height;
    d.DepthOrArraySize = uint16_t(desc.arrayLayers);
    d.MipLevels = uint16_t(desc.mipLevels);
    d.Format = toDxgiResourceFormat(desc.format);
    d.SampleDesc.Count = 1;
    d.Layout = D3D12_TEXTURE_LAYOUT_UNKNOWN;
    uint32_t flags = D3D12_RESOURCE_FLAG_NONE;
    if (hasAny(desc.usage, TextureUsage::Storage)) flags |= D3D12_RESOURCE_FLAG_ALLOW_UNORDERED_ACCESS;
    if (hasAny(desc.usage, TextureUsage::RenderTarget)) flags |= D3D12_RESOURCE_FLAG_ALLOW_RENDER_TARGET;
    if (hasAny(desc.usage, TextureUsage::DepthStencil)) flags |= D3D12_RESOURCE_FLAG_ALLOW_DEPTH_STENCIL;
    d.Flags = D3D12_RESOURCE_FLAGS(flags);
    return d;
}

D3D12_HEAP_TYPE heapTypeOf(MemoryType m) {
    switch (m) {
        case MemoryType::Upload: return D3D12_HEAP_TYPE_UPLOAD;
        case MemoryType::Readback: return D3D12_HEAP_TYPE_READBACK;
        default: return D3D12_HEAP_TYPE_DEFAULT;
    }
}

// Upload heaps must start (and stay) in GENERIC_READ, readback heaps in COPY_DEST (D3D12_HEAP_TYPE docs).
D3D12_RESOURCE_STATES initialStateOf(MemoryType m, bool accelStruct) {
    if (m == MemoryType::Upload) return D3D12_RESOURCE_STATE_GENERIC_READ;
    if (m == MemoryType::Readback) return D3D12_RESOURCE_STATE_COPY_DEST;
    return accelStruct ? D3D12_RESOURCE_STATE_RAYTRACING_ACCELERATION_STRUCTURE : D3D12_RESOURCE_STATE_COMMON;
}

D3D12_CLEAR_VALUE clearValueFor(const TextureDesc& desc) {
    D3D12_CLEAR_VALUE v{};
    if (hasAny(desc.usage, TextureUsage::DepthStencil)) {
        v.Format = toDxgiDsvFormat(desc.format);
        v.DepthStencil = {1.0f, 0};
    } else {
        v.Format = toDxgiFormat(desc.format);
        std::memcpy(v.Color, desc.clearColor, sizeof(v.Color));
    }
    return v;
}

bool needsClearValue(const TextureDesc& desc) {
    return hasAny(desc.usage, TextureUsage::RenderTarget | TextureUsage::DepthStencil);
}

}  // namespace

Result<ComPtr<ID3D12Resource>> createCommittedBuffer(ID3D12Device* device, uint64_t bytes, D3D12_HEAP_TYPE heap,
                                                     D3D12_RESOURCE_FLAGS flags, D3D12_RESOURCE_STATES state,
                                                     const std::string& name) {
    D3D12_HEAP_PROPERTIES props{};
    props.Type = heap;
    D3D12_RESOURCE_DESC d = bufferResourceDesc(bytes, flags);
    ComPtr<ID3D12Resource> r;
    if (!succeeded(device->CreateCommittedResource(&props, D3D12_HEAP_FLAG_NONE, &d, state, nullptr,
                                                   __uuidof(ID3D12Resource), r.putVoid())))
        return makeError("d3d12: could not create buffer '" + name + "' of " + std::to_string(bytes) + " bytes");
    setDebugName(r.get(), name);
    return r;
}

Result<BufferHandle> Device::createBuffer(const BufferDesc& desc) {
    auto b = std::make_shared<Buffer>();
    b->releases = releases_;
    b->desc_ = desc;
    const bool as = hasAny(desc.usage, BufferUsage::AccelStructStorage);
    b->state = initialStateOf(desc.memory, as);
    if (desc.isVirtual) return BufferHandle(b);   // memory comes from bindMemory
    D3D12_HEAP_PROPERTIES props{};
    props.Type = heapTypeOf(desc.memory);
    D3D12_RESOURCE_DESC d = bufferDescFor(desc);
    if (!succeeded(device_->CreateCommittedResource(&props, D3D12_HEAP_FLAG_NONE, &d, b->state, nullptr,
                                                    __uuidof(ID3D12Resource), b->resource.putVoid())))
        return makeError("d3d12: could not create buffer '" + desc.debugName + "'");
    setDebugName(b->resource.get(), desc.debugName);
    if (desc.memory != MemoryType::DeviceLocal) b->resource->Map(0, nullptr, &b->mapped);
    return BufferHandle(b);
}

Result<TextureHandle> Device::createTexture(const TextureDesc& desc) {
    if (toDxgiFormat(desc.format) == DXGI_FORMAT_UNKNOWN)
        return makeError("d3d12: texture '" + desc.debugName + "' has no D3D12 format");
    auto t = std::make_shared<Texture>();
    t->releases = releases_;
    t->desc_ = desc;
    if (desc.isVirtual) return TextureHandle(t);
    D3D12_HEAP_PROPERTIES props{};
    props.Type = D3D12_HEAP_TYPE_DEFAULT;
    D3D12_RESOURCE_DESC d = textureDescFor(desc);
    D3D12_CLEAR_VALUE clear = clearValueFor(desc);
    if (!succeeded(device_->CreateCommittedResource(&props, D3D12_HEAP_FLAG_NONE, &d, t->state,
                                                    needsClearValue(desc) ? &clear : nullptr,
                                                    __uuidof(ID3D12Resource), t->resource.putVoid())))
        return makeError("d3d12: could not create texture '" + desc.debugName + "'");
    setDebugName(t->resource.get(), desc.debugName);
    return TextureHandle(t);
}

Result<SamplerHandle> Device::createSampler(const SamplerDesc& desc) {
    auto s = std::make_shared<Sampler>();
    s->desc_ = desc;   // the descriptor itself is written into each binding set that uses it
    return SamplerHandle(s);
}

Result<HeapHandle> Device::createHeap(const HeapDesc& desc) {
    auto h = std::make_shared<Heap>();
    h->releases = releases_;
    h->desc_ = desc;
    D3D12_HEAP_DESC d{};
    d.SizeInBytes = desc.byteSize;
    d.Properties.Type = D3D12_HEAP_TYPE_DEFAULT;
    // 64 KiB alignment covers buffers and non-MSAA textures; ALLOW_ALL_BUFFERS_AND_TEXTURES needs
    // resource heap tier 2, which every DXR-capable GPU has.
    d.Alignment = D3D12_DEFAULT_RESOURCE_PLACEMENT_ALIGNMENT;
    d.Flags = D3D12_HEAP_FLAG_ALLOW_ALL_BUFFERS_AND_TEXTURES;
    if (!succeeded(device_->CreateHeap(&d, __uuidof(ID3D12Heap), h->heap.putVoid())))
        return makeError("d3d12: could not create heap '" + desc.debugName + "' of " + std::to_string(desc.byteSize) + " bytes");
    setDebugName(h->heap.get(), desc.debugName);
    return HeapHandle(h);
}

MemoryRequirements Device::memoryRequirements(const TextureDesc& desc) {
    D3D12_RESOURCE_DESC d = textureDescFor(desc);
    D3D12_RESOURCE_ALLOCATION_INFO info = resourceAllocationInfo(device_.get(), 0, 1, &d);
    return {info.SizeInBytes, info.Alignment};
}

MemoryRequirements Device::memoryRequirements(const BufferDesc& desc) {
    D3D12_RESOURCE_DESC d = bufferDescFor(desc);
    D3D12_RESOURCE_ALLOCATION_INFO info = resourceAllocationInfo(device_.get(), 0, 1, &d);
    return {info.SizeInBytes, info.Alignment};
}

Status Device::bindMemory(const TextureHandle& texture, const HeapHandle& heap, uint64_t offset) {
    auto* t = static_cast<Texture*>(texture.get());
    if (!t->desc_.isVirtual || t->resource) return makeError("d3d12 bindMemory: texture '" + t->desc_.debugName + "' is not an unbound virtual texture");
    D3D12_RESOURCE_DESC d = textureDescFor(t->desc_);
    D3D12_CLEAR_VALUE clear = clearValueFor(t->desc_);
    if (!succeeded(device_->CreatePlacedResource(static_cast<Heap*>(heap.get())->heap.get(), offset, &d, t->state,
                                                 needsClearValue(t->desc_) ? &clear : nullptr,
                                                 __uuidof(ID3D12Resource), t->resource.putVoid())))
        return makeError("d3d12 bindMemory: could not place texture '" + t->desc_.debugName + "'");
    setDebugName(t->resource.get(), t->desc_.debugName);
    return okStatus();
}

Status Device::bindMemory(const BufferHandle& buffer, const HeapHandle& heap, uint64_t offset) {
    auto* b = static_cast<Buffer*>(buffer.get());
    if (!b->desc_.isVirtual || b->resource || b->desc_.memory != MemoryType::DeviceLocal)
        return makeError("d3d12 bindMemory: buffer '" + b->desc_.debugName + "' is not an unbound device-local virtual buffer");
    D3D12_RESOURCE_DESC d = bufferDescFor(b->desc_);
    if (!succeeded(device_->CreatePlacedResource(static_cast<Heap*>(heap.get())->heap.get(), offset, &d, b->state,
                                                 nullptr, __uuidof(ID3D12Resource), b->resource.putVoid())))
        return makeError("d3d12 bindMemory: could not place buffer '" + b->desc_.debugName + "'");
    setDebugName(b->resource.get(), b->desc_.debugName);
    return okStatus();
}

}  // namespace caustics::rhi::d3d12
