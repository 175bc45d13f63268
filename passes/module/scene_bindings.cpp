#include "caustics/scene_bindings.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "caustics/gpu_light.h"

namespace caustics {

Result<rhi::BindingLayoutHandle> SceneBindings::createLayout(rhi::IDevice& device) {
    namespace s = scene_slots;
    rhi::BindingLayoutDesc layoutDesc;
    layoutDesc.setVisibility(rhi::ShaderStage::All)
        .add(s::kTlas, rhi::BindingType::AccelStruct)
        .add(s::kPositions, rhi::BindingType::StorageBufferRO)
        .add(s::kVertices, rhi::BindingType::StorageBufferRO)
        .add(s::kIndices, rhi::BindingType::StorageBufferRO)
        .add(s::kMaterials, rhi::BindingType::StorageBufferRO)
        .add(s::kInstances, rhi::BindingType::StorageBufferRO)
        .add(s::kLights, rhi::BindingType::StorageBufferRO)
        .add(s::kSampler, rhi::BindingType::Sampler)
        .add(s::kTextures, rhi::BindingType::SampledTexture, kMaxSceneTextures);
    return device.createBindingLayout(layoutDesc);
}

Result<rhi::BindingSetHandle> SceneBindings::createSet(rhi::IDevice& device, const rhi::BindingLayoutHandle& layout,
                                                       const rhi::SamplerHandle& sampler,
                                                       const std::vector<rhi::TextureHandle>& textures,
                                                       const SceneTables& tables) {
    namespace s = scene_slots;
    if (!tables.tlas || !tables.positions || !tables.vertices || !tables.indices || !tables.materials ||
        !tables.instances || !tables.lights)
        return makeError("SceneBindings: a scene table (TLAS, positions, vertices, indices, materials, instances or lights) is missing");
    if (textures.empty()) return makeError("SceneBindings: the GPU scene has no texture (expected at least a white 1x1)");
    if (textures.size() > kMaxSceneTextures)
        return makeError("SceneBindings: the scene has " + std::to_string(textures.size()) +
                         " textures, more than kMaxSceneTextures = " + std::to_string(kMaxSceneTextures));
    rhi::BindingSetDesc setDesc;
    setDesc.add(rhi::BindingSetItem::accelStructItem(s::kTlas, tables.tlas))
        .add(rhi::BindingSetItem::storageBuffer(s::kPositions, tables.positions, false))
        .add(rhi::BindingSetItem::storageBuffer(s::kVertices, tables.vertices, false))
        .add(rhi::BindingSetItem::storageBuffer(s::kIndices, tables.indices, false))
        .add(rhi::BindingSetItem::storageBuffer(s::kMaterials, tables.materials, false))
        .add(rhi::BindingSetItem::storageBuffer(s::kInstances, tables.instances, false))
        .add(rhi::BindingSetItem::storageBuffer(s::kLights, tables.lights, false))
        .add(rhi::BindingSetItem::samplerItem(s::kSampler, sampler));
    // Every element of an array binding must be written (binding.h); spare slots repeat texture 0.
    for (uint32_t i = 0; i < kMaxSceneTextures; ++i) {
        const auto& tex = i < textures.size() ? textures[i] : textures[0];
        setDesc.add(rhi::BindingSetItem::sampledTexture(s::kTextures, tex, i));
    }
    return device.createBindingSet(setDesc, layout);
}

Result<SceneBindings> SceneBindings::create(rhi::IDevice& device, const scene::GpuScene& gpuScene,
                                            const scene::Scene& scene) {
    if (scene.instances.empty())
        return makeError("scene '" + scene.name + "' has no mesh instances: nothing to render or trace");
    if (!gpuScene.tlas) return makeError("SceneBindings: the GPU scene has no TLAS (built with buildAccelStructs off?)");

    SceneBindings b;
    // The light table lives in host-visible memory: it is written once here, and host writes made
    // before a submit are visible to it (Vulkan spec 7.9, "host write ordering guarantees").
    std::vector<uint8_t> lightBytes = packLightBuffer(scene.lights);
    lightBytes.resize(std::max<size_t>(lightBytes.size(), 16 + 64), 0);   // never an empty array
    CAUSTICS_TRY(b.lights, device.createBuffer(rhi::BufferDesc()
                                                   .setByteSize(lightBytes.size())
                                                   .setUsage(rhi::BufferUsage::Storage)
                                                   .setMemory(rhi::MemoryType::Upload)
                                                   .setDebugName("scene lights")));
    if (!b.lights->mappedData()) return makeError("SceneBindings: the light buffer is not host-visible");
    std::memcpy(b.lights->mappedData(), lightBytes.data(), lightBytes.size());
    b.lightCount = uint32_t(scene.lights.size());

    CAUSTICS_TRY(b.sampler, device.createSampler(rhi::SamplerDesc().setFilter(rhi::FilterMode::Linear)
                                                     .setAddress(rhi::AddressMode::Repeat)));
    CAUSTICS_TRY(b.layout, createLayout(device));
    CAUSTICS_TRY(b.set, createSet(device, b.layout, b.sampler, gpuScene.textures,
                                  SceneTables{gpuScene.tlas, gpuScene.positions, gpuScene.vertices, gpuScene.indices,
                                              gpuScene.materials, gpuScene.instances, b.lights}));
    return b;
}

}  // namespace caustics
