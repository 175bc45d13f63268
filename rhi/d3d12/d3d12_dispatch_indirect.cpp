// dispatchIndirect on D3D12: ExecuteIndirect with a command signature whose one argument is
// D3D12_INDIRECT_ARGUMENT_TYPE_DISPATCH. D3D12_DISPATCH_ARGUMENTS is the RHI's argument as it is
// (three uint32 group counts, Vulkan's VkDispatchIndirectCommand), so the caller's buffer is read in place.
#include "d3d12_command_list.h"

namespace caustics::rhi::d3d12 {

void CommandList::dispatchIndirect(const BufferHandle& args, uint64_t offset) {
    auto* src = static_cast<Buffer*>(args.get());
    if (!src || !hasAny(src->desc_.usage, BufferUsage::Indirect) || offset % 4 != 0 || offset + 12 > src->desc_.byteSize)
        return fail(makeError("d3d12 dispatchIndirect: the argument buffer needs BufferUsage::Indirect and 12 bytes "
                              "at a 4-aligned offset"));
    if (!dispatchSignature) {
        D3D12_INDIRECT_ARGUMENT_DESC argument{};
        argument.Type = D3D12_INDIRECT_ARGUMENT_TYPE_DISPATCH;
        D3D12_COMMAND_SIGNATURE_DESC d{};
        d.ByteStride = sizeof(D3D12_DISPATCH_ARGUMENTS);
        d.NumArgumentDescs = 1;
        d.pArgumentDescs = &argument;
        // No root arguments change, so no root signature (D3D12 spec: null is then required).
        if (!succeeded(device->d3d()->CreateCommandSignature(&d, nullptr, __uuidof(ID3D12CommandSignature),
                                                            dispatchSignature.putVoid())))
            return fail(makeError("d3d12 dispatchIndirect: CreateCommandSignature failed"));
    }
    list->ExecuteIndirect(dispatchSignature.get(), 1, src->resource.get(), offset, nullptr, 0);
}

}  // namespace caustics::rhi::d3d12
