// dispatchRaysIndirect on D3D12: ExecuteIndirect with a command signature whose one argument is
// D3D12_INDIRECT_ARGUMENT_TYPE_DISPATCH_RAYS (DXR 1.1, raytracing tier 1.1). That argument is a whole
// D3D12_DISPATCH_RAYS_DESC, shader-table addresses included, while the RHI's argument is only the grid
// (Vulkan's VkTraceRaysIndirectCommandKHR). So each call assembles the desc in a small default-heap
// buffer: the shader-table part is uploaded from the host, the grid is copied on the GPU timeline from
// the caller's buffer into Width/Height/Depth, then ExecuteIndirect reads it.
#include <cstddef>

#include "d3d12_command_list.h"

namespace caustics::rhi::d3d12 {

void CommandList::dispatchRaysIndirect(const BufferHandle& args, uint64_t offset) {
    if (!table) return fail(makeError("d3d12 dispatchRaysIndirect: no shader table set"));
    if (!device->capabilities().rayTracingIndirect)
        return fail(makeError("d3d12 dispatchRaysIndirect: the device has no raytracing tier 1.1"));
    auto* src = static_cast<Buffer*>(args.get());
    if (!src || !hasAny(src->desc_.usage, BufferUsage::Indirect) || offset % 4 != 0 || offset + 12 > src->desc_.byteSize)
        return fail(makeError("d3d12 dispatchRaysIndirect: the argument buffer needs BufferUsage::Indirect and 12 "
                              "bytes at a 4-aligned offset"));
    if (!dispatchRaysSignature) {
        D3D12_INDIRECT_ARGUMENT_DESC argument{};
        argument.Type = D3D12_INDIRECT_ARGUMENT_TYPE_DISPATCH_RAYS;
        D3D12_COMMAND_SIGNATURE_DESC d{};
        d.ByteStride = sizeof(D3D12_DISPATCH_RAYS_DESC);
        d.NumArgumentDescs = 1;
        d.pArgumentDescs = &argument;
        // No root arguments change, so no root signature (D3D12 spec: null is then required).
        if (!succeeded(device->d3d()->CreateCommandSignature(&d, nullptr, __uuidof(ID3D12CommandSignature),
                                                            dispatchRaysSignature.putVoid())))
            return fail(makeError("d3d12 dispatchRaysIndirect: CreateCommandSignature failed"));
    }
    const D3D12_DISPATCH_RAYS_DESC tableDesc =
        makeDispatchRaysDesc(table->layout, table->buffer->GetGPUVirtualAddress(), 0, 0, 0);
    auto staged = upload(&tableDesc, sizeof(tableDesc));
    if (!staged) return;
    auto argument = createCommittedBuffer(device->d3d(), sizeof(tableDesc), D3D12_HEAP_TYPE_DEFAULT,
                                          D3D12_RESOURCE_FLAG_NONE, D3D12_RESOURCE_STATE_COPY_DEST,
                                          "dispatchRaysIndirect argument");
    if (!argument) return fail(argument.error());
    keep(argument.value());
    ID3D12Resource* desc = argument.value().get();
    list->CopyBufferRegion(desc, 0, staged.get(), 0, sizeof(tableDesc));
    // The caller left `args` in IndirectArgument; a copy needs COPY_SOURCE for its duration.
    D3D12_RESOURCE_BARRIER toCopy{};
    toCopy.Type = D3D12_RESOURCE_BARRIER_TYPE_TRANSITION;
    toCopy.Transition = {src->resource.get(), D3D12_RESOURCE_BARRIER_ALL_SUBRESOURCES, D3D12_RESOURCE_STATE_INDIRECT_ARGUMENT,
                         D3D12_RESOURCE_STATE_COPY_SOURCE};
    const bool moveSource = src->desc_.memory == MemoryType::DeviceLocal;   // upload heaps stay GENERIC_READ
    if (moveSource) list->ResourceBarrier(1, &toCopy);
    list->CopyBufferRegion(desc, offsetof(D3D12_DISPATCH_RAYS_DESC, Width), src->resource.get(), offset, 12);
    D3D12_RESOURCE_BARRIER after[2]{};
    after[0] = toCopy;
    std::swap(after[0].Transition.StateBefore, after[0].Transition.StateAfter);
    after[1].Type = D3D12_RESOURCE_BARRIER_TYPE_TRANSITION;
    after[1].Transition = {desc, D3D12_RESOURCE_BARRIER_ALL_SUBRESOURCES, D3D12_RESOURCE_STATE_COPY_DEST,
                           D3D12_RESOURCE_STATE_INDIRECT_ARGUMENT};
    list->ResourceBarrier(moveSource ? 2 : 1, moveSource ? after : after + 1);
    list->ExecuteIndirect(dispatchRaysSignature.get(), 1, desc, 0, nullptr, 0);
}

}  // namespace caustics::rhi::d3d12
