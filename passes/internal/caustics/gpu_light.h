#pragma once
// Lights as the shaders see them (struct GpuLight in shaders/common/scene.h, checked member for member
// in passes/module/scene_layout_check.cpp).
// KHR_lights_punctual units: point/spot `intensity` = colour x candela, directional = colour x lux.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "caustics/scene/scene.h"

namespace caustics {

enum GpuLightType : uint32_t { kGpuLightPoint = 0, kGpuLightSpot = 1, kGpuLightDirectional = 2 };

struct GpuLight {
    glm::vec3 position{0.0f};
    uint32_t type = kGpuLightPoint;
    glm::vec3 direction{0.0f, -1.0f, 0.0f};   // unit; where the light shines
    float range = 0.0f;                       // 0 = infinite
    glm::vec3 intensity{0.0f};                // colour x intensity
    float cosInner = 1.0f;                    // spot cone cosines
    float cosOuter = 0.0f;
    uint32_t castsCaustics = 1;               // reserved for the caustic passes (map skipping)
    uint32_t pad0 = 0, pad1 = 0;
};
static_assert(sizeof(GpuLight) == 64);
static_assert(offsetof(GpuLight, direction) == 16);
static_assert(offsetof(GpuLight, intensity) == 32);
static_assert(offsetof(GpuLight, cosOuter) == 48);

GpuLight toGpuLight(const scene::Light& light);

// The light buffer's bytes: its header (GpuLightTableHeader in shaders/common/scene.h, the count) followed
// by count GpuLight, and room for one light at least.
std::vector<uint8_t> packLightBuffer(const std::vector<scene::Light>& lights);

}  // namespace caustics
