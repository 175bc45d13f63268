// Built instead of the backend when DirectX-Headers were not found at configure time.
#include "../../factory/backend_entry_points.h"

namespace caustics::rhi::d3d12 {

Result<DeviceHandle> createDevice(const DeviceDesc&) {
    return makeError("d3d12 backend: this build of the caustics library was configured without it "
                     "(DirectX-Headers not found; Debian/Ubuntu: apt-get install directx-headers-dev, then "
                     "re-run CMake)");
}

}  // namespace caustics::rhi::d3d12
