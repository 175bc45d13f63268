// Imports of a host engine's resources and command list on D3D12 (d3d12_interop.h). Each RHI object
// holds a COM reference to the host's object and starts from the state the host declared.
#include <string>

#include "caustics/rhi/d3d12_interop.h"
#include "d3d12_command_list.h"
#include "d3d12_device.h"
#include "d3d12_objects.h"
#include "format_translation.h"
#include "host_objects.h"

namespace caustics::rhi {
namespace {

Result<d3d12::Device*> d3d12Device(IDevice& device, const char* call, const std::string& name) {
    if (device.backend() != Backend::D3D12)
        return makeError(std::string(call) + " '" + name + "': the device is not a D3D12 device");
    return static_cast<d3d12::Device*>(&device);
}

D3D12_RESOURCE_DESC resourceDesc(ID3D12Resource* resource) { return d3d12::describe<D3D12_RESOURCE_DESC>(resource); }

}  // namespace

Result<TextureHandle> importD3D12Texture(IDevice& device, const D3D12TextureImport& desc) {
    CAUSTICS_TRY(d3d12::Device * dev, d3d12Device(device, "importD3D12Texture", desc.debugName));
    if (!desc.resource) return makeError("d3d12: cannot import texture '" + desc.debugName + "': resource is null");
    const D3D12_RESOURCE_DESC rd = resourceDesc(desc.resource);
    D3D12TextureFacts facts{uint32_t(rd.Dimension), uint32_t(rd.Format), rd.Width, rd.Height,
                            rd.DepthOrArraySize, rd.MipLevels, uint32_t(rd.Flags)};
    CAUSTICS_TRY(TextureDesc td, textureDescFromD3D12(facts, desc.uses, desc.cube, desc.debugName));
    CAUSTICS_TRY(ResourceState state, resourceStateFromD3D12(desc.currentStates));
    (void)state;   // validated; the backend tracks the native states below
    if (hasAny(desc.uses, TextureUsage::Storage)) {
        // Typed UAV stores depend on the format and the device (D3D12 "Typed unordered access view loads").
        D3D12_FEATURE_DATA_FORMAT_SUPPORT support{d3d12::toDxgiFormat(td.format)};
        if (!d3d12::succeeded(dev->d3d()->CheckFeatureSupport(D3D12_FEATURE_FORMAT_SUPPORT, &support, sizeof(support))) ||
            !(support.Support2 & D3D12_FORMAT_SUPPORT2_UAV_TYPED_STORE))
            return makeError("d3d12: cannot import texture '" + desc.debugName + "': use Storage: format " +
                             formatInfo(td.format).name + " has no typed UAV store on this device");
    }
    auto texture = std::make_shared<d3d12::Texture>();
    texture->desc_ = td;
    texture->resource = d3d12::holdReference(desc.resource);
    texture->state = D3D12_RESOURCE_STATES(desc.currentStates);
    return TextureHandle(texture);
}

Result<BufferHandle> importD3D12Buffer(IDevice& device, const D3D12BufferImport& desc) {
    CAUSTICS_TRY(d3d12::Device * dev, d3d12Device(device, "importD3D12Buffer", desc.debugName));
    (void)dev;
    const std::string what = "d3d12: cannot import buffer '" + desc.debugName + "'";
    if (!desc.resource) return makeError(what + ": resource is null");
    const D3D12_RESOURCE_DESC rd = resourceDesc(desc.resource);
    if (rd.Dimension != D3D12_RESOURCE_DIMENSION_BUFFER) return makeError(what + ": the resource is not a buffer");
    // Acceleration-structure storage must allow unordered access (D3D12 raytracing spec, "Acceleration structure memory").
    if (hasAny(desc.uses, BufferUsage::AccelStructStorage) && !(rd.Flags & D3D12_RESOURCE_FLAG_ALLOW_UNORDERED_ACCESS))
        return makeError(what + ": use AccelStructStorage needs D3D12_RESOURCE_FLAG_ALLOW_UNORDERED_ACCESS");
    CAUSTICS_TRY(ResourceState state, resourceStateFromD3D12(desc.currentStates));
    (void)state;
    auto buffer = std::make_shared<d3d12::Buffer>();
    buffer->desc_.byteSize = rd.Width;
    buffer->desc_.usage = desc.uses;
    buffer->desc_.memory = MemoryType::DeviceLocal;
    buffer->desc_.structStride = desc.structStride;
    buffer->desc_.debugName = desc.debugName;
    buffer->resource = d3d12::holdReference(desc.resource);
    buffer->state = D3D12_RESOURCE_STATES(desc.currentStates);
    return BufferHandle(buffer);
}

Result<AccelStructHandle> importD3D12AccelStruct(IDevice& device, const D3D12AccelStructImport& desc) {
    CAUSTICS_TRY(d3d12::Device * dev, d3d12Device(device, "importD3D12AccelStruct", desc.debugName));
    (void)dev;
    if (!desc.storage)
        return makeError("d3d12: cannot import acceleration structure '" + desc.debugName + "': storage is null");
    if (desc.offset % D3D12_RAYTRACING_ACCELERATION_STRUCTURE_BYTE_ALIGNMENT != 0)
        return makeError("d3d12: cannot import acceleration structure '" + desc.debugName + "': offset " +
                         std::to_string(desc.offset) + " is not a multiple of 256");
    auto as = std::make_shared<d3d12::AccelStruct>();
    as->desc_.isTopLevel = desc.isTopLevel;
    as->desc_.debugName = desc.debugName;
    as->storage = d3d12::holdReference(desc.storage);
    as->storageOffset = desc.offset;
    as->storageSize = resourceDesc(desc.storage).Width - desc.offset;
    return AccelStructHandle(as);
}

Result<CommandListHandle> wrapD3D12CommandList(IDevice& device, const D3D12CommandListImport& desc) {
    CAUSTICS_TRY(d3d12::Device * dev, d3d12Device(device, "wrapD3D12CommandList", desc.debugName));
    if (!desc.commandList) return makeError("d3d12: wrapD3D12CommandList '" + desc.debugName + "': commandList is null");
    auto list = std::make_shared<d3d12::CommandList>();
    list->device = dev;
    list->list = d3d12::holdReference(desc.commandList);
    list->timestampsAllowed = desc.allowTimestamps;
    CAUSTICS_CHECK(list->createDescriptorStorage(dev->d3d()));
    list->hostHeaps[0] = desc.hostDescriptorHeaps[0];
    list->hostHeaps[1] = desc.hostDescriptorHeaps[1];
    list->begin();   // no allocator: resets our rings and sets our shader-visible heaps on the host's list
    list->restoreHostHeaps();   // ours again at each pass (beginMarker)
    return CommandListHandle(list);
}

Result<D3D12SubmitSignal> d3d12SubmitSignal(IDevice& device, ICommandList& wrapped) {
    CAUSTICS_TRY(d3d12::Device * dev, d3d12Device(device, "d3d12SubmitSignal", "host command list"));
    auto& list = static_cast<d3d12::CommandList&>(wrapped);
    if (list.allocator) return makeError("d3d12SubmitSignal: the command list is the module's own; IDevice::submit signals for it");
    if (!list.firstError.ok()) return list.firstError.error();
    auto [fence, value] = dev->reserveHostSignal();
    return D3D12SubmitSignal{fence, value};
}

}  // namespace caustics::rhi
