#pragma once
// The GPU scene's binding set (set 0 of every pass that traces or shades scene geometry), declared once
// (docs/shaders.md, "Bindings"): the build generates its GLSL and HLSL declarations, bindings/scene.h,
// which common/scene_resources.h reads the scene through; caustics::SceneBindings creates the layout
// and fills the set by these names (passes/module/scene_bindings.cpp). The element structs are the
// shared dialect's common/scene.h; strides, header size and matrix offsets are held against their C++
// compilation by binding_truth_tests (SceneSetBindings.*).
#include <cstdint>

#include "bindings/shader_binding.h"

namespace caustics::shader_bindings {

// The bindless texture array's size. A fixed size keeps the layout free of descriptor-indexing
// features; unused slots hold the scene's first texture.
inline constexpr uint32_t kSceneTextureCount = 256;

inline constexpr MatrixMember kGpuInstanceMatrices[] = {{"objectToWorld", 0}, {"normalToWorld", 64}};

// Raster and compute shaders define SCENE_NO_TLAS (an acceleration-structure type is invalid SPIR-V
// without a ray-tracing capability, and vs/ps/cs have no DXR types); a pass that reads no texture
// defines SCENE_NO_TEXTURES.
inline constexpr Binding kSceneSetBindingList[] = {
    {.name = "sceneTlas", .kind = Kind::AccelStruct, .set = 0, .slot = 0, .element = "", .omitIf = "SCENE_NO_TLAS"},
    {"scenePositions", Kind::StorageBufferRO, 0, 1, "float"},   // 3 per vertex: the BLAS input
    {.name = "sceneVertices", .kind = Kind::StorageBufferRO, .set = 0, .slot = 2, .element = "GpuVertex", .stride = 48},
    {"sceneIndices", Kind::StorageBufferRO, 0, 3, "uint"},   // relative to the instance's firstVertex
    {.name = "sceneMaterials", .kind = Kind::StorageBufferRO, .set = 0, .slot = 4, .element = "GpuMaterial", .stride = 96},
    // Indexed by the TLAS instance id.
    {.name = "sceneInstances", .kind = Kind::StorageBufferRO, .set = 0, .slot = 5, .element = "GpuInstance",
     .stride = 160, .matrices = kGpuInstanceMatrices},
    // The light table: its count, then the lights (caustics::packLightBuffer).
    {.name = "sceneLights", .kind = Kind::StorageBufferRO, .set = 0, .slot = 6, .element = "GpuLight", .stride = 64,
     .header = "GpuLightTableHeader", .headerBytes = 16},
    {.name = "sceneSampler", .kind = Kind::Sampler, .set = 0, .slot = 7, .element = "", .omitIf = "SCENE_NO_TEXTURES"},
    // RGBA8_SRGB, indexed by GpuMaterial::baseColorTexture.
    {.name = "sceneTextures", .kind = Kind::SampledTexture, .set = 0, .slot = 8, .element = "float4",
     .count = kSceneTextureCount, .omitIf = "SCENE_NO_TEXTURES"},
};

inline constexpr PassBindings kSceneSetBindings{"scene", "passes/module/scene_set_bindings.h", kSceneSetBindingList, "",
                                                ""};

}  // namespace caustics::shader_bindings
