// Binding layouts and sets: each set's descriptors are written once into CPU staging heaps at the
// offsets computed by computeDescriptorTableLayout (descriptor_layout.h).
#include "d3d12_device.h"
#include "d3d12_objects.h"
#include "format_translation.h"

namespace caustics::rhi::d3d12 {
namespace {

D3D12_TEXTURE_ADDRESS_MODE addressMode(AddressMode m) {
    switch (m) {
        case AddressMode::ClampToEdge: return D3D12_TEXTURE_ADDRESS_MODE_CLAMP;
        case AddressMode::MirroredRepeat: return D3D12_TEXTURE_ADDRESS_MODE_MIRROR;
        default: return D3D12_TEXTURE_ADDRESS_MODE_WRAP;
    }
}

// Storage-buffer views are always raw (ByteAddressBuffer, R32_TYPELESS, 4-byte elements), whatever
// BufferDesc::structStride says: an HLSL declaration must match the view kind, and the HLSL of every
// pass (shaders/d3d12) reads std430-laid-out data through ByteAddressBuffer so that one shader works
// with any buffer (headers + arrays, float3 members at std430 offsets). structStride is informative.
void bufferViewShape(const Buffer& b, const BindingSetItem& item, UINT64& first, UINT& count, UINT& stride,
                     DXGI_FORMAT& format, bool& raw) {
    const uint64_t range = item.range ? item.range : b.desc_.byteSize - item.offset;
    raw = true;
    stride = 0;
    first = item.offset / 4;   // raw views address in 4-byte units; the offset must be 16-byte aligned
    count = UINT(range / 4);
    format = DXGI_FORMAT_R32_TYPELESS;
}

Status writeDescriptor(ID3D12Device5* device, const BindingSetItem& item, D3D12_CPU_DESCRIPTOR_HANDLE dst) {
    const std::string what = "binding at slot " + std::to_string(item.slot);
    switch (item.type) {
        case BindingType::ConstantBuffer: {
            auto* b = static_cast<Buffer*>(item.buffer.get());
            if (!b) return makeError(what + ": no buffer");
            const uint64_t range = item.range ? item.range : b->desc_.byteSize - item.offset;
            D3D12_CONSTANT_BUFFER_VIEW_DESC v{b->deviceAddress() + item.offset, UINT(alignUp(range, 256))};
            device->CreateConstantBufferView(&v, dst);
            return okStatus();
        }
        case BindingType::StorageBufferRO:
        case BindingType::StorageBufferRW: {
            auto* b = static_cast<Buffer*>(item.buffer.get());
            if (!b) return makeError(what + ": no buffer");
            UINT64 first;
            UINT count, stride;
            DXGI_FORMAT format;
            bool raw;
            bufferViewShape(*b, item, first, count, stride, format, raw);
            if (item.type == BindingType::StorageBufferRO) {
                D3D12_SHADER_RESOURCE_VIEW_DESC v{};
                v.Format = format;
                v.ViewDimension = D3D12_SRV_DIMENSION_BUFFER;
                v.Shader4ComponentMapping = D3D12_DEFAULT_SHADER_4_COMPONENT_MAPPING;
                v.Buffer = {first, count, stride, raw ? D3D12_BUFFER_SRV_FLAG_RAW : D3D12_BUFFER_SRV_FLAG_NONE};
                device->CreateShaderResourceView(b->resource.get(), &v, dst);
            } else {
                D3D12_UNORDERED_ACCESS_VIEW_DESC v{};
                v.Format = format;
                v.ViewDimension = D3D12_UAV_DIMENSION_BUFFER;
                v.Buffer = {first, count, stride, 0, raw ? D3D12_BUFFER_UAV_FLAG_RAW : D3D12_BUFFER_UAV_FLAG_NONE};
                device->CreateUnorderedAccessView(b->resource.get(), nullptr, &v, dst);
            }
            return okStatus();
        }
        case BindingType::SampledTexture: {
            auto* t = static_cast<Texture*>(item.texture.get());
            if (!t) return makeError(what + ": no texture");
            const TextureDesc& d = t->desc_;
            D3D12_SHADER_RESOURCE_VIEW_DESC v{};
            v.Format = toDxgiSrvFormat(d.format);
            v.Shader4ComponentMapping = D3D12_DEFAULT_SHADER_4_COMPONENT_MAPPING;
            if (d.dimension == TextureDimension::TextureCube) {
                v.ViewDimension = D3D12_SRV_DIMENSION_TEXTURECUBE;
                v.TextureCube.MipLevels = d.mipLevels;
            } else if (d.dimension == TextureDimension::Texture2DArray || d.arrayLayers > 1) {
                v.ViewDimension = D3D12_SRV_DIMENSION_TEXTURE2DARRAY;
                v.Texture2DArray.MipLevels = d.mipLevels;
                v.Texture2DArray.ArraySize = d.arrayLayers;
            } else {
                v.ViewDimension = D3D12_SRV_DIMENSION_TEXTURE2D;
                v.Texture2D.MipLevels = d.mipLevels;
            }
            device->CreateShaderResourceView(t->resource.get(), &v, dst);
            return okStatus();
        }
        case BindingType::StorageTexture: {
            auto* t = static_cast<Texture*>(item.texture.get());
            if (!t) return makeError(what + ": no texture");
            D3D12_UNORDERED_ACCESS_VIEW_DESC v{};
            v.Format = toDxgiFormat(t->desc_.format);
            if (t->desc_.arrayLayers > 1) {
                v.ViewDimension = D3D12_UAV_DIMENSION_TEXTURE2DARRAY;
                v.Texture2DArray.ArraySize = t->desc_.arrayLayers;
            } else {
                v.ViewDimension = D3D12_UAV_DIMENSION_TEXTURE2D;
            }
            device->CreateUnorderedAccessView(t->resource.get(), nullptr, &v, dst);
            return okStatus();
        }
        case BindingType::AccelStruct: {
            if (!item.accelStruct) return makeError(what + ": no acceleration structure");
            D3D12_SHADER_RESOURCE_VIEW_DESC v{};
            v.ViewDimension = D3D12_SRV_DIMENSION_RAYTRACING_ACCELERATION_STRUCTURE;
            v.Shader4ComponentMapping = D3D12_DEFAULT_SHADER_4_COMPONENT_MAPPING;
            v.RaytracingAccelerationStructure.Location = item.accelStruct->deviceAddress();
            device->CreateShaderResourceView(nullptr, &v, dst);   // DXR: the resource is null, the address says all
            return okStatus();
        }
        case BindingType::Sampler: {
            if (!item.sampler) return makeError(what + ": no sampler");
            const SamplerDesc& s = item.sampler->desc();
            D3D12_SAMPLER_DESC v{};
            v.Filter = s.maxAnisotropy > 1.0f ? D3D12_FILTER_ANISOTROPIC
                       : s.filter == FilterMode::Linear ? D3D12_FILTER_MIN_MAG_MIP_LINEAR
                                                        : D3D12_FILTER_MIN_MAG_MIP_POINT;
            v.AddressU = v.AddressV = v.AddressW = addressMode(s.address);
            v.MaxAnisotropy = UINT(s.maxAnisotropy);
            v.ComparisonFunc = D3D12_COMPARISON_FUNC_NEVER;
            v.MaxLOD = D3D12_FLOAT32_MAX;
            device->CreateSampler(&v, dst);
            return okStatus();
        }
    }
    return makeError(what + ": unknown binding type");
}

}  // namespace

BindingSet::~BindingSet() {
    if (resourceHeap) resourceHeap->release(resources);
    if (samplerHeap) samplerHeap->release(samplers);
}

Result<BindingLayoutHandle> Device::createBindingLayout(const BindingLayoutDesc& desc) {
    auto layout = std::make_shared<BindingLayout>();
    layout->desc_ = desc;
    CAUSTICS_TRY(layout->table, computeDescriptorTableLayout(desc));
    return BindingLayoutHandle(layout);
}

Result<BindingSetHandle> Device::createBindingSet(const BindingSetDesc& desc, const BindingLayoutHandle& layoutHandle) {
    auto* layout = static_cast<BindingLayout*>(layoutHandle.get());
    if (!layout) return makeError("d3d12 createBindingSet: no layout");
    auto set = std::make_shared<BindingSet>();
    set->desc_ = desc;
    set->layout_ = layoutHandle;
    set->resourceHeap = cpuResources_.get();
    set->samplerHeap = cpuSamplers_.get();
    CAUSTICS_TRY(set->resources, cpuResources_->allocate(layout->table.resourceDescriptorCount));
    CAUSTICS_TRY(set->samplers, cpuSamplers_->allocate(layout->table.samplerDescriptorCount));
    for (const BindingSetItem& item : desc.items) {
        auto offset = layout->table.offsetOf(item.type, item.slot, item.arrayElement);
        if (!offset)
            return makeError("d3d12 createBindingSet: the layout has no " + std::string(1, registerLetter(registerClassOf(item.type))) +
                             std::to_string(item.slot) + "[" + std::to_string(item.arrayElement) + "] of that type");
        CpuDescriptorHeap& heap = item.type == BindingType::Sampler ? *cpuSamplers_ : *cpuResources_;
        const DescriptorRange& range = item.type == BindingType::Sampler ? set->samplers : set->resources;
        CAUSTICS_CHECK(writeDescriptor(device_.get(), item, heap.at(range.first + *offset)));
    }
    return BindingSetHandle(set);
}

}  // namespace caustics::rhi::d3d12
