// caustics::rhi::d3d12::createDevice: loads the runtime libraries, then hands over to Device::create.
#include "../factory/backend_entry_points.h"
#include "d3d12_device.h"
#include "runtime_library.h"

namespace caustics::rhi::d3d12 {

Result<RuntimeLibraries> loadRuntimeLibraries() {
    RuntimeLibraries libs;
    auto d3d12 = RuntimeLibrary::open(d3d12LibraryCandidates(), d3d12LibraryAdvice());
    if (!d3d12) return makeError("d3d12 backend: " + d3d12.message());
    libs.d3d12 = std::move(d3d12).value();
    // Passes ship HLSL, so a device without the compiler could not run them: refuse it up front.
    auto dxc = RuntimeLibrary::open(dxcompilerLibraryCandidates(), dxcompilerLibraryAdvice());
    if (!dxc) return makeError("d3d12 backend: " + dxc.message());
    libs.dxcompiler = std::move(dxc).value();
    // DXCore is optional: without it the default adapter is used.
    auto dxcore = RuntimeLibrary::open(dxcoreLibraryCandidates(), "");
    if (dxcore) libs.dxcore = std::move(dxcore).value();
    return libs;
}

Result<DeviceHandle> createDevice(const DeviceDesc& desc) {
    CAUSTICS_TRY(RuntimeLibraries libs, loadRuntimeLibraries());
    return Device::create(desc, std::move(libs));
}

}  // namespace caustics::rhi::d3d12
