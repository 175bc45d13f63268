// Placeholder replaced by the Vulkan backend.
#include "../factory/backend_entry_points.h"
namespace caustics::rhi::vulkan {
Result<DeviceHandle> createDevice(const DeviceDesc&) { return makeError("vulkan backend: not built yet"); }
}
