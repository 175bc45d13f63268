#pragma once
// Test harness around CausticsModule: renders one frame of a scene and reads chosen graph outputs
// back (G-buffer targets, the linear HDR image of the selected AOV). Shared by tests/image.
#include <cstdint>
#include <memory>
#include <vector>

#include "caustics/caustics_module.h"
#include "caustics/rhi/device.h"
#include "caustics/scene/gpu_scene.h"

namespace caustics::test {

struct RenderedFrame {
    uint32_t width = 0, height = 0;
    std::vector<float> hdr;                // RGBA32F, settings.aov in linear units
    std::vector<uint32_t> objectId;        // R32_UINT
    std::vector<float> linearDepth;        // R32_FLOAT
    std::vector<float> normalRoughness;    // RGBA (converted from half)
};

// Creates the GPU scene and the module, renders one frame with `camera`, reads everything back.
// Errors carry the failing step's message.
Result<RenderedFrame> renderFrame(const rhi::DeviceHandle& device, const scene::Scene& scene,
                                  const CausticsSettings& settings, const scene::Camera& camera, uint32_t width,
                                  uint32_t height);

float halfToFloat(uint16_t h);

}  // namespace caustics::test
