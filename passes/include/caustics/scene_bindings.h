#pragma once
// The GPU scene as one binding set (descriptor set), the layout shaders/vulkan/scene/scene.glsl
// declares (binding numbers are listed there). Every pass that traces or shades scene geometry binds
// it, by default as set 0. Built once per scene; the lights buffer is owned here.
#include <cstdint>

#include "caustics/rhi/device.h"
#include "caustics/rhi/result.h"
#include "caustics/scene/gpu_scene.h"
#include "caustics/scene/scene.h"

namespace caustics {

// Size of the bindless texture array (SCENE_MAX_TEXTURES in scene.glsl). A fixed size keeps the
// layout free of descriptor-indexing features; unused slots hold the scene's first texture.
inline constexpr uint32_t kMaxSceneTextures = 256;

namespace scene_slots {
inline constexpr uint32_t kTlas = 0, kPositions = 1, kVertices = 2, kIndices = 3, kMaterials = 4,
                          kInstances = 5, kLights = 6, kSampler = 7, kTextures = 8;
}

struct SceneBindings {
    rhi::BindingLayoutHandle layout;
    rhi::BindingSetHandle set;
    rhi::BufferHandle lights;     // header + GpuLight[] (caustics/gpu_light.h)
    rhi::SamplerHandle sampler;
    uint32_t lightCount = 0;

    // Fails when the scene has more than kMaxSceneTextures textures (message says how many) or no TLAS.
    static Result<SceneBindings> create(rhi::IDevice& device, const scene::GpuScene& gpuScene,
                                        const scene::Scene& scene);
};

}  // namespace caustics
