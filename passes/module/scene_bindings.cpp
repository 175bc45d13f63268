#include "caustics/scene_bindings.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "caustics/gpu_light.h"

namespace caustics {

Result<SceneBindings> SceneBindings::create(rhi::IDevice& device, const scene::GpuScene& gpuScene,
                                            const scene::Scene& scene) {
    namespace s = scene_slots;
    if (scene.instances.empty())
        return makeError("scene '" + scene.name + "' has no mesh instances: nothing to render or trace");
    if (!gpuScene.tlas) return makeError("SceneBindings: the GPU scene has no TLAS (built with buildAccelStructs off?)");
    if (gpuScene.textures.empty()) return makeError("SceneBindings: the GPU scene has no texture (expected at least a white 1x1)");
    if (gpuScene.textures.size() > kMaxSceneTextures)
        return makeError("SceneBindings: the scene has " + std::to_string(gpuScene.textures.size()) +
                         " textures, more than kMaxSceneTextures = " + std::to_string(kMaxSceneTextures));

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
    CAUSTICS_TRY(b.layout, device.createBindingLayout(layoutDesc));

    rhi::BindingSetDesc setDesc;
    setDesc.add(rhi::BindingSetItem::accelStructItem(s::kTlas, gpuScene.tlas))
        .add(rhi::BindingSetItem::storageBuffer(s::kPositions, gpuScene.positions, false))
        .add(rhi::BindingSetItem::storageBuffer(s::kVertices, gpuScene.vertices, false))
        .add(rhi::BindingSetItem::storageBuffer(s::kIndices, gpuScene.indices, false))
        .add(rhi::BindingSetItem::storageBuffer(s::kMaterials, gpuScene.materials, false))
        .add(rhi::BindingSetItem::storageBuffer(s::kInstances, gpuScene.instances, false))
        .add(rhi::BindingSetItem::storageBuffer(s::kLights, b.lights, false))
        .add(rhi::BindingSetItem::samplerItem(s::kSampler, b.sampler));
    // Every element of an array binding must be written (binding.h); spare slots repeat texture 0.
    for (uint32_t i = 0; i < kMaxSceneTextures; ++i) {
        const auto& tex = i < gpuScene.textures.size() ? gpuScene.textures[i] : gpuScene.textures[0];
        setDesc.add(rhi::BindingSetItem::sampledTexture(s::kTextures, tex, i));
    }
    CAUSTICS_TRY(b.set, device.createBindingSet(setDesc, b.layout));
    return b;
}

}  // namespace caustics
