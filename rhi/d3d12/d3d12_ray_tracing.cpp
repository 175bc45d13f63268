// State objects, shader tables and acceleration structures (DXR spec). The translation itself is in
// state_object_builder / shader_table_image / accel_struct_inputs; this file talks to the device.
#include <cstring>

#include "accel_struct_inputs.h"
#include "d3d12_device.h"
#include "d3d12_objects.h"
#include "state_object_builder.h"

namespace caustics::rhi::d3d12 {

Result<RootBinding> makeRootBinding(Device& device, const PipelineBindings& bindings, RootSignatureKind kind,
                                    const std::string& name);

Result<StateObjectHandle> Device::createStateObject(const StateObjectDesc& desc) {
    if (!caps_.rayTracingPipeline) return makeError("d3d12: '" + desc.debugName + "' needs DXR, which this device lacks");
    auto so = std::make_shared<StateObject>();
    so->releases = releases_;
    so->desc_ = desc;
    CAUSTICS_TRY(so->root, makeRootBinding(*this, desc.globalBindings, RootSignatureKind::Compute, desc.debugName));
    if (desc.localBindings.localDataBytes > 0) {
        CAUSTICS_TRY(RootSignatureLayout local, localRootSignatureLayout(desc.localBindings.localDataBytes));
        CAUSTICS_TRY(so->localRootSignature, createRootSignature(local, desc.debugName + " (local)"));
    }
    std::vector<std::vector<uint8_t>> code;
    for (const ShaderLibraryDesc& lib : desc.libraries) {
        CAUSTICS_TRY(std::vector<uint8_t> bytes, bytecodeFor(lib.code, "", ShaderStage::RayGen, true));
        code.push_back(std::move(bytes));
    }
    StateObjectInputs inputs;
    for (const auto& c : code) inputs.libraryBytecode.emplace_back(c);
    inputs.globalRootSignature = so->root.rootSignature.get();
    inputs.localRootSignature = so->localRootSignature.get();
    StateObjectBuilder builder;
    CAUSTICS_CHECK(builder.build(desc, inputs));
    if (!succeeded(device_->CreateStateObject(&builder.desc(), __uuidof(ID3D12StateObject), so->stateObject.putVoid())))
        return makeError("d3d12: CreateStateObject failed for '" + desc.debugName +
                         "' (enable validation for the debug layer's reason)");
    ComPtr<ID3D12StateObjectProperties> props;
    so->stateObject->QueryInterface(__uuidof(ID3D12StateObjectProperties), props.putVoid());
    for (const std::string& name : builder.shaderTableNames()) {
        std::wstring w(name.begin(), name.end());
        const void* id = props->GetShaderIdentifier(w.c_str());
        if (!id) return makeError("d3d12: state object '" + desc.debugName + "' has no identifier for '" + name + "'");
        const auto* bytes = static_cast<const uint8_t*>(id);
        so->identifiers[name].assign(bytes, bytes + D3D12_SHADER_IDENTIFIER_SIZE_IN_BYTES);
    }
    return StateObjectHandle(so);
}

Result<ShaderTableHandle> Device::createShaderTable(const ShaderTableDesc& desc) {
    auto* so = static_cast<StateObject*>(desc.stateObject.get());
    if (!so) return makeError("d3d12 shader table '" + desc.debugName + "': no state object");
    CAUSTICS_TRY(ShaderTableImage image,
                 buildShaderTableImage(desc, so->desc_.localBindings.localDataBytes,
                                       [so](const std::string& n) { return so->shaderIdentifier(n); }));
    auto table = std::make_shared<ShaderTable>();
    table->releases = releases_;
    table->desc_ = desc;
    table->layout = image.layout;
    // Upload heap: placed resources start at 64 KiB boundaries, so the 64-byte table alignment holds.
    CAUSTICS_TRY(table->buffer, createCommittedBuffer(device_.get(), image.bytes.size(), D3D12_HEAP_TYPE_UPLOAD,
                                                      D3D12_RESOURCE_FLAG_NONE, D3D12_RESOURCE_STATE_GENERIC_READ,
                                                      desc.debugName));
    void* mapped = nullptr;
    table->buffer->Map(0, nullptr, &mapped);
    std::memcpy(mapped, image.bytes.data(), image.bytes.size());
    table->buffer->Unmap(0, nullptr);
    return ShaderTableHandle(table);
}

namespace {
Status allocateAccelStruct(ID3D12Device5* device, AccelStruct& as,
                           const D3D12_BUILD_RAYTRACING_ACCELERATION_STRUCTURE_INPUTS& inputs) {
    D3D12_RAYTRACING_ACCELERATION_STRUCTURE_PREBUILD_INFO info{};
    device->GetRaytracingAccelerationStructurePrebuildInfo(&inputs, &info);
    if (info.ResultDataMaxSizeInBytes == 0)
        return makeError("d3d12: acceleration structure '" + as.desc_.debugName + "' has no prebuild size");
    as.storageSize = alignUp(info.ResultDataMaxSizeInBytes, D3D12_RAYTRACING_ACCELERATION_STRUCTURE_BYTE_ALIGNMENT);
    const uint64_t scratch = std::max(info.ScratchDataSizeInBytes, info.UpdateScratchDataSizeInBytes);
    CAUSTICS_TRY(as.storage, createCommittedBuffer(device, as.storageSize, D3D12_HEAP_TYPE_DEFAULT,
                                                   D3D12_RESOURCE_FLAG_ALLOW_UNORDERED_ACCESS,
                                                   D3D12_RESOURCE_STATE_RAYTRACING_ACCELERATION_STRUCTURE,
                                                   as.desc_.debugName));
    CAUSTICS_TRY(as.scratch, createCommittedBuffer(device, scratch, D3D12_HEAP_TYPE_DEFAULT,
                                                   D3D12_RESOURCE_FLAG_ALLOW_UNORDERED_ACCESS,
                                                   D3D12_RESOURCE_STATE_UNORDERED_ACCESS, as.desc_.debugName + " scratch"));
    return okStatus();
}
}  // namespace

Result<AccelStructHandle> Device::createAccelStruct(const AccelStructDesc& desc) {
    auto as = std::make_shared<AccelStruct>();
    as->releases = releases_;
    as->desc_ = desc;
    if (desc.isTopLevel) {
        CAUSTICS_CHECK(allocateAccelStruct(device_.get(), *as, makeTopLevelInputs(desc, 0, desc.maxInstances, false)));
        const uint64_t bytes = std::max<uint64_t>(desc.maxInstances, 1) * sizeof(D3D12_RAYTRACING_INSTANCE_DESC);
        CAUSTICS_TRY(as->instances, createCommittedBuffer(device_.get(), bytes, D3D12_HEAP_TYPE_UPLOAD,
                                                          D3D12_RESOURCE_FLAG_NONE, D3D12_RESOURCE_STATE_GENERIC_READ,
                                                          desc.debugName + " instances"));
        as->instances->Map(0, nullptr, &as->instancesMapped);
    } else {
        BottomLevelInputs inputs;
        makeBottomLevelInputs(desc, false, inputs);
        CAUSTICS_CHECK(allocateAccelStruct(device_.get(), *as, inputs.inputs));
    }
    return AccelStructHandle(as);
}

Result<AccelStructHandle> Device::compactAccelStruct(const AccelStructHandle& builtHandle) {
    auto* built = static_cast<AccelStruct*>(builtHandle.get());
    if (!built || !hasAny(built->desc_.flags, AccelBuildFlags::AllowCompaction))
        return makeError("d3d12 compactAccelStruct: '" + (built ? built->desc_.debugName : "") + "' was not built with AllowCompaction");
    // Post-build info is written by the GPU into a UAV buffer, then copied to a readback buffer.
    CAUSTICS_TRY(auto info, createCommittedBuffer(device_.get(), 8, D3D12_HEAP_TYPE_DEFAULT,
                                                  D3D12_RESOURCE_FLAG_ALLOW_UNORDERED_ACCESS,
                                                  D3D12_RESOURCE_STATE_UNORDERED_ACCESS, "compaction size"));
    CAUSTICS_TRY(auto readback, createCommittedBuffer(device_.get(), 8, D3D12_HEAP_TYPE_READBACK, D3D12_RESOURCE_FLAG_NONE,
                                                      D3D12_RESOURCE_STATE_COPY_DEST, "compaction size readback"));
    CAUSTICS_CHECK(runImmediate([&](ID3D12GraphicsCommandList4* list) {
        D3D12_RAYTRACING_ACCELERATION_STRUCTURE_POSTBUILD_INFO_DESC post{
            info->GetGPUVirtualAddress(), D3D12_RAYTRACING_ACCELERATION_STRUCTURE_POSTBUILD_INFO_COMPACTED_SIZE};
        D3D12_GPU_VIRTUAL_ADDRESS source = built->deviceAddress();
        list->EmitRaytracingAccelerationStructurePostbuildInfo(&post, 1, &source);
        D3D12_RESOURCE_BARRIER b{};
        b.Type = D3D12_RESOURCE_BARRIER_TYPE_TRANSITION;
        b.Transition = {info.get(), 0, D3D12_RESOURCE_STATE_UNORDERED_ACCESS, D3D12_RESOURCE_STATE_COPY_SOURCE};
        list->ResourceBarrier(1, &b);
        list->CopyResource(readback.get(), info.get());
    }));
    uint64_t compactedSize = 0;
    void* mapped = nullptr;
    readback->Map(0, nullptr, &mapped);
    std::memcpy(&compactedSize, mapped, 8);
    readback->Unmap(0, nullptr);

    auto out = std::make_shared<AccelStruct>();
    out->releases = releases_;
    out->desc_ = built->desc_;
    out->storageSize = alignUp(compactedSize, D3D12_RAYTRACING_ACCELERATION_STRUCTURE_BYTE_ALIGNMENT);
    CAUSTICS_TRY(out->storage, createCommittedBuffer(device_.get(), out->storageSize, D3D12_HEAP_TYPE_DEFAULT,
                                                     D3D12_RESOURCE_FLAG_ALLOW_UNORDERED_ACCESS,
                                                     D3D12_RESOURCE_STATE_RAYTRACING_ACCELERATION_STRUCTURE,
                                                     built->desc_.debugName + " compacted"));
    CAUSTICS_CHECK(runImmediate([&](ID3D12GraphicsCommandList4* list) {
        list->CopyRaytracingAccelerationStructure(out->deviceAddress(), built->deviceAddress(),
                                                  D3D12_RAYTRACING_ACCELERATION_STRUCTURE_COPY_MODE_COMPACT);
    }));
    return AccelStructHandle(out);
}

}  // namespace caustics::rhi::d3d12
