#include "caustics/rhi/device.h"

namespace caustics::rhi {

const char* backendName(Backend backend) {
    return backend == Backend::Vulkan ? "vulkan" : "d3d12";
}

std::optional<Backend> parseBackend(std::string_view name) {
    if (name == "vulkan") return Backend::Vulkan;
    if (name == "d3d12") return Backend::D3D12;
    return std::nullopt;
}

}  // namespace caustics::rhi
