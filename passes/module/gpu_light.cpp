#include "caustics/gpu_light.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "common/scene.h"

namespace caustics {

GpuLight toGpuLight(const scene::Light& light) {
    GpuLight g;
    switch (light.type) {
        case scene::LightType::Point: g.type = kGpuLightPoint; break;
        case scene::LightType::Spot: g.type = kGpuLightSpot; break;
        case scene::LightType::Directional: g.type = kGpuLightDirectional; break;
    }
    g.position = light.position;
    float len = glm::length(light.direction);
    g.direction = len > 0.0f ? light.direction / len : glm::vec3(0.0f, -1.0f, 0.0f);
    g.range = light.range;
    g.intensity = light.color * light.intensity;
    g.cosInner = std::cos(light.innerConeAngle);
    g.cosOuter = std::cos(light.outerConeAngle);
    return g;
}

std::vector<uint8_t> packLightBuffer(const std::vector<scene::Light>& lights) {
    shader::GpuLightTableHeader header{};
    header.count = uint32_t(lights.size());
    // Room for one light at least: a storage buffer is never empty.
    std::vector<uint8_t> bytes(sizeof(header) + sizeof(GpuLight) * std::max<size_t>(lights.size(), 1), 0);
    std::memcpy(bytes.data(), &header, sizeof(header));
    for (size_t i = 0; i < lights.size(); ++i) {
        GpuLight g = toGpuLight(lights[i]);
        std::memcpy(bytes.data() + sizeof(header) + i * sizeof(GpuLight), &g, sizeof(GpuLight));
    }
    return bytes;
}

}  // namespace caustics
