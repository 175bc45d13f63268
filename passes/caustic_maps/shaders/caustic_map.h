#ifndef CAUSTICS_PASS_CAUSTIC_MAP_H
#define CAUSTICS_PASS_CAUSTIC_MAP_H
// caustics.maps in the shared dialect (paper 3.2, Figure 3; docs/shaders.md): each map layer is a
// raster from its light of the instances it may see, one draw per instance (the instance index is
// the draw's first instance), pulling the vertices from the scene buffers; the target holds the
// objectId (instance index + 1; 0 = empty) of the surface nearest the light. The forward trace reads
// only this: it emits from the light through specular texels and finds the exact hit itself, so no
// position or normal target is written. Entries: caustic_map.vert / .frag, caustic_map.hlsl.
#include "common/caustic_map.h"
#include "common/scene.h"

CAUSTICS_SHARED_BEGIN
// Push constants (caustic_map_bindings.h), 4 bytes.
struct CausticMapParams {
    uint mapIndex;   // the layer drawn
};

CAUSTICS_FN uint causticMapObjectId(uint instance) { return instance + 1u; }
CAUSTICS_SHARED_END

// The vertex stage's resources and functions (the fragment stage defines CAUSTIC_MAP_FRAGMENT: it
// reads no resource).
#if !defined(CAUSTICS_LANG_CPP) && !defined(CAUSTIC_MAP_FRAGMENT)
#include "bindings/caustic_map.h"   // generated from passes/caustic_maps/caustic_map_bindings.h

// The layer's world -> clip transform (Vulkan clip). HLSL reads the matrix column by column
// (common/lang.h), not through the templated load.
float4x4 causticMapViewProj(uint layer) {
#if defined(CAUSTICS_LANG_GLSL)
    return maps[layer].viewProj;
#else
    return loadFloat4x4(maps, 176u * layer + 96u);   // CausticMap::viewProj
#endif
}

// Clip position of vertex `vertexIndex` (of the draw) of scene instance `instance`.
float4 causticMapVertex(uint instance, uint vertexIndex) {
    GpuInstance inst = sceneInstance(instance);
    uint v = inst.firstVertex + sceneIndex(inst.firstIndex + vertexIndex);
    float4 world = mat4Mul(inst.objectToWorld, float4(scenePosition(v), 1.0f));
    return mat4Mul(causticMapViewProj(params.mapIndex), world);
}
#endif  // !CAUSTICS_LANG_CPP && !CAUSTIC_MAP_FRAGMENT

#endif  // CAUSTICS_PASS_CAUSTIC_MAP_H
