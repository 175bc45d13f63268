#pragma once
// The GPU scene as one binding set (descriptor set), declared once in passes/module/scene_set_bindings.h
// (its names, slots and element types; the shaders include the declarations generated from it). Every
// pass that traces or shades scene geometry binds it, by default as set 0. SceneBindings::create binds a
// frozen scene (lights uploaded once; tests and tools); the module binds a live scene through one
// SceneBindings per frame-in-flight slot whose tables and TLAS it rewrites every frame
// (passes/module/live_scene.h, docs/embedding.md).
#include <cstdint>

#include "caustics/rhi/device.h"
#include "caustics/rhi/result.h"
#include "caustics/scene/gpu_scene.h"
#include "caustics/scene/scene.h"

namespace caustics {

// What set 0 binds besides the textures (layouts: caustics/scene/gpu_types.h, caustics/host_scene.h).
struct SceneTables {
    rhi::AccelStructHandle tlas;
    rhi::BufferHandle positions, vertices, indices;
    rhi::BufferHandle materials;  // GpuMaterial[]
    rhi::BufferHandle instances;  // GpuInstance[], indexed by the TLAS instance id
    rhi::BufferHandle lights;     // header + GpuLight[] (caustics/gpu_light.h)

    bool operator==(const SceneTables&) const = default;
};

struct SceneBindings {
    rhi::BindingLayoutHandle layout;
    rhi::BindingSetHandle set;
    rhi::BufferHandle lights;     // header + GpuLight[] (caustics/gpu_light.h)
    rhi::SamplerHandle sampler;
    uint32_t lightCount = 0;

    // The layout of set 0 (the same object for every slot, so pipelines are built once).
    static Result<rhi::BindingLayoutHandle> createLayout(rhi::IDevice& device);
    // Set 0 over `tables` and `textures` (at least one, at most the declared array's kSceneTextureCount).
    static Result<rhi::BindingSetHandle> createSet(rhi::IDevice& device, const rhi::BindingLayoutHandle& layout,
                                                   const rhi::SamplerHandle& sampler,
                                                   const std::vector<rhi::TextureHandle>& textures,
                                                   const SceneTables& tables);

    // Fails when the scene has more textures than the array holds (message says how many) or no TLAS.
    static Result<SceneBindings> create(rhi::IDevice& device, const scene::GpuScene& gpuScene,
                                        const scene::Scene& scene);
};

}  // namespace caustics
