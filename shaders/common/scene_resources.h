#ifndef CAUSTICS_COMMON_SCENE_RESOURCES_H
#define CAUSTICS_COMMON_SCENE_RESOURCES_H
// The GPU scene as a GLSL or HLSL shader reads it (docs/shaders.md, "Scene API"): the set's
// declarations are generated from their one C++ declaration (passes/module/scene_set_bindings.h), and
// this file defines over their <name>Load accessors the functions common/scene.h reads the scene
// through. Define before including: SCENE_NO_TLAS in raster and compute shaders, SCENE_NO_TEXTURES where
// a pass reads no texture, and SCENE_UNIFORM_TEXTURE_INDEX where the material is dynamically uniform
// (one draw per instance), which drops the non-uniform index qualifier (and, on Vulkan, its
// SampledImageArrayNonUniformIndexing capability). Not for C++: a C++ caller defines the accessors.
#if !defined(__cplusplus) && !defined(__HLSL_VERSION)
// GLSL (common/lang.h's test, spelled here: an #extension precedes the declarations it allows).
#extension GL_EXT_nonuniform_qualifier : enable
#endif
#include "common/scene.h"
#include "bindings/scene.h"

#if defined(CAUSTICS_LANG_GLSL)
#define SCENE_NONUNIFORM(i) nonuniformEXT(i)
#define SCENE_SAMPLE_LOD0(tex, smp, uv) textureLod(sampler2D((tex), (smp)), (uv), 0.0)
#else
#define SCENE_NONUNIFORM(i) NonUniformResourceIndex(i)
#define SCENE_SAMPLE_LOD0(tex, smp, uv) (tex).SampleLevel((smp), (uv), 0.0f)
#endif

GpuInstance sceneInstance(uint i) { return sceneInstancesLoad(i); }
GpuVertex sceneVertex(uint i) { return sceneVerticesLoad(i); }
GpuMaterial sceneMaterial(uint i) { return sceneMaterialsLoad(i); }
uint sceneIndex(uint i) { return sceneIndicesLoad(i); }
uint sceneLightCount() { return sceneLightsLoadHeader().count; }
GpuLight sceneLight(uint i) { return sceneLightsLoad(i); }
float3 scenePosition(uint vertex) {
    return float3(scenePositionsLoad(3u * vertex), scenePositionsLoad(3u * vertex + 1u), scenePositionsLoad(3u * vertex + 2u));
}

// Linear base colour of a material at uv (the texture is sRGB-encoded; the view decodes it). The index
// is non-uniform in hit and ray-generation shaders.
float3 sceneBaseColor(GpuMaterial m, float2 uv) {
    float3 c = m.baseColor;
#ifndef SCENE_NO_TEXTURES
    if (m.baseColorTexture >= 0) {
        int t = m.baseColorTexture;
#ifdef SCENE_UNIFORM_TEXTURE_INDEX
        c *= SCENE_SAMPLE_LOD0(sceneTextures[t], sceneSampler, uv).rgb;
#else
        c *= SCENE_SAMPLE_LOD0(sceneTextures[SCENE_NONUNIFORM(t)], sceneSampler, uv).rgb;
#endif
    }
#endif
    return c;
}

#endif  // CAUSTICS_COMMON_SCENE_RESOURCES_H
