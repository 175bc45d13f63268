// d3d12_interop.h when the backend was configured out (no DirectX-Headers): every entry says so.
#include "caustics/rhi/d3d12_interop.h"

namespace caustics::rhi {
namespace {
Error unavailable(const char* call) {
    return makeError(std::string(call) + ": this build of the caustics library has no D3D12 backend "
                     "(DirectX-Headers not found at configure time)");
}
}  // namespace

Status checkD3D12DeviceRequirements(const D3D12FeatureReport&, bool, std::string_view) {
    return unavailable("checkD3D12DeviceRequirements");
}
Result<DeviceHandle> wrapD3D12Device(const D3D12DeviceImport&) { return unavailable("wrapD3D12Device"); }
Result<ResourceState> resourceStateFromD3D12(uint32_t) { return unavailable("resourceStateFromD3D12"); }
Result<TextureHandle> importD3D12Texture(IDevice&, const D3D12TextureImport&) {
    return unavailable("importD3D12Texture");
}
Result<TextureDesc> textureDescFromD3D12(const D3D12TextureFacts&, TextureUsage, bool, const std::string&) {
    return unavailable("textureDescFromD3D12");
}
Result<BufferHandle> importD3D12Buffer(IDevice&, const D3D12BufferImport&) { return unavailable("importD3D12Buffer"); }
Result<AccelStructHandle> importD3D12AccelStruct(IDevice&, const D3D12AccelStructImport&) {
    return unavailable("importD3D12AccelStruct");
}
Result<CommandListHandle> wrapD3D12CommandList(IDevice&, const D3D12CommandListImport&) {
    return unavailable("wrapD3D12CommandList");
}
Result<D3D12SubmitSignal> d3d12SubmitSignal(IDevice&, ICommandList&) { return unavailable("d3d12SubmitSignal"); }

}  // namespace caustics::rhi
