#include "backend_entry_points.h"

namespace caustics::rhi {

Result<DeviceHandle> createDevice(const DeviceDesc& desc) {
    switch (desc.backend) {
        case Backend::Vulkan: return vulkan::createDevice(desc);
        case Backend::D3D12:
#if defined(CAUSTICS_HAS_D3D12)
            return d3d12::createDevice(desc);
#else
            return makeError("d3d12 backend: this build of the caustics library was configured without it "
                             "(CAUSTICS_WITH_D3D12=OFF or DirectX-Headers not found)");
#endif
    }
    return makeError("createDevice: unknown backend");
}

}  // namespace caustics::rhi
