#ifndef CAUSTICS_SCENE_SCENE_GLSL
#define CAUSTICS_SCENE_SCENE_GLSL
// Vulkan declarations of the GPU scene as bound by caustics::SceneBindings
// (passes/internal/caustics/scene_bindings.h); the structs and the surface of a hit are the shared
// dialect's common/scene.h and common/scene.h (docs/shaders.md, "Scene API"). One descriptor
// set, by default set 0 (define SCENE_SET before including to move it). Define SCENE_NO_TEXTURES to
// leave the texture array out of a shader, and SCENE_UNIFORM_TEXTURE_INDEX where the material is
// dynamically uniform (one draw per instance), which drops the nonuniformEXT qualifier (and its
// SampledImageArrayNonUniformIndexing capability). Raster and compute shaders without ray queries
// must define SCENE_NO_TLAS (an acceleration-structure type is invalid SPIR-V without a ray-tracing
// capability).
#ifndef SCENE_NO_TLAS
#extension GL_EXT_ray_tracing : enable
#endif
#extension GL_EXT_nonuniform_qualifier : enable
#include "common/scene.h"

#ifndef SCENE_SET
#define SCENE_SET 0
#endif
// Must equal caustics::kMaxSceneTextures.
#define SCENE_MAX_TEXTURES 256

#ifndef SCENE_NO_TLAS
layout(set = SCENE_SET, binding = 0) uniform accelerationStructureEXT sceneTlas;   // instanceId = instance index
#endif
layout(set = SCENE_SET, binding = 1, std430) readonly buffer ScenePositions { float scenePositions[]; };
layout(set = SCENE_SET, binding = 2, std430) readonly buffer SceneVertices { GpuVertex sceneVertices[]; };
layout(set = SCENE_SET, binding = 3, std430) readonly buffer SceneIndices { uint sceneIndices[]; };   // relative to firstVertex
layout(set = SCENE_SET, binding = 4, std430) readonly buffer SceneMaterials { GpuMaterial sceneMaterials[]; };
layout(set = SCENE_SET, binding = 5, std430) readonly buffer SceneInstances { GpuInstance sceneInstances[]; };
layout(set = SCENE_SET, binding = 6, std430) readonly buffer SceneLights {
    uint sceneLightTotal; uint sceneLightPad0; uint sceneLightPad1; uint sceneLightPad2;
    GpuLight sceneLights[];
};
#ifndef SCENE_NO_TEXTURES
layout(set = SCENE_SET, binding = 7) uniform sampler sceneSampler;   // linear, repeat
layout(set = SCENE_SET, binding = 8) uniform texture2D sceneTextures[SCENE_MAX_TEXTURES];   // RGBA8_SRGB
#endif

// The accessors common/scene.h reads the scene through (the D3D12 shim has the same).
GpuInstance sceneInstance(uint i) { return sceneInstances[i]; }
GpuVertex sceneVertex(uint i) { return sceneVertices[i]; }
GpuMaterial sceneMaterial(uint i) { return sceneMaterials[i]; }
uint sceneIndex(uint i) { return sceneIndices[i]; }
uint sceneLightCount() { return sceneLightTotal; }
GpuLight sceneLight(uint i) { return sceneLights[i]; }
vec3 scenePosition(uint vertex) {
    return vec3(scenePositions[3 * vertex], scenePositions[3 * vertex + 1], scenePositions[3 * vertex + 2]);
}

// Linear base colour of a material at uv (texture is sRGB-encoded; the sampler decodes it). The index
// is non-uniform in hit shaders, hence nonuniformEXT.
vec3 sceneBaseColor(GpuMaterial m, vec2 uv) {
    vec3 c = m.baseColor;
#ifndef SCENE_NO_TEXTURES
    if (m.baseColorTexture >= 0) {
        int t = m.baseColorTexture;
#ifdef SCENE_UNIFORM_TEXTURE_INDEX
        c *= textureLod(sampler2D(sceneTextures[t], sceneSampler), uv, 0.0).rgb;
#else
        c *= textureLod(sampler2D(sceneTextures[nonuniformEXT(t)], sceneSampler), uv, 0.0).rgb;
#endif
    }
#endif
    return c;
}

#endif
