#include "caustics/scene_bindings.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "caustics/gpu_light.h"
#include "module/pass_bindings.h"
#include "module/scene_set_bindings.h"

namespace caustics {

namespace {
const shader_bindings::PassBindings& kSet = shader_bindings::kSceneSetBindings;
constexpr uint32_t kTextureCount = shader_bindings::kSceneTextureCount;
}  // namespace

Result<rhi::BindingLayoutHandle> SceneBindings::createLayout(rhi::IDevice& device) {
    return createPassBindingLayout(device, kSet, 0, rhi::ShaderStage::All);
}

Result<rhi::BindingSetHandle> SceneBindings::createSet(rhi::IDevice& device, const rhi::BindingLayoutHandle& layout,
                                                       const rhi::SamplerHandle& sampler,
                                                       const std::vector<rhi::TextureHandle>& textures,
                                                       const SceneTables& tables) {
    if (!tables.tlas || !tables.positions || !tables.vertices || !tables.indices || !tables.materials ||
        !tables.instances || !tables.lights)
        return makeError("SceneBindings: a scene table (TLAS, positions, vertices, indices, materials, instances or lights) is missing");
    if (textures.empty()) return makeError("SceneBindings: the GPU scene has no texture (expected at least a white 1x1)");
    if (textures.size() > kTextureCount)
        return makeError("SceneBindings: the scene has " + std::to_string(textures.size()) +
                         " textures, more than the scene set's array holds (kSceneTextureCount = " +
                         std::to_string(kTextureCount) + ")");
    // Every element of an array binding must be written (binding.h); spare slots repeat texture 0.
    std::vector<rhi::TextureHandle> array(kTextureCount, textures[0]);
    std::copy(textures.begin(), textures.end(), array.begin());
    CAUSTICS_TRY(rhi::BindingSetDesc setDesc, PassBindingSet(kSet, 0)
                                                  .accelStruct("sceneTlas", tables.tlas)
                                                  .buffer("scenePositions", tables.positions)
                                                  .buffer("sceneVertices", tables.vertices)
                                                  .buffer("sceneIndices", tables.indices)
                                                  .buffer("sceneMaterials", tables.materials)
                                                  .buffer("sceneInstances", tables.instances)
                                                  .buffer("sceneLights", tables.lights)
                                                  .sampler("sceneSampler", sampler)
                                                  .textures("sceneTextures", array)
                                                  .desc());
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
