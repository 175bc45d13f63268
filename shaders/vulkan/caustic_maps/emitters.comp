#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// caustics.emitters: the map texels that emit photons, compacted into a list, and the forward pass's
// indirect grid (list length x samples per texel). The paper (3.2) emits only where the map sees a
// specular surface; testing that here instead of in every forward launch makes the forward dispatch,
// and so its cost, follow the specular texels instead of the whole map (docs/caustics.md, "Cost").
// A texel emits when its 3x3 neighbourhood sees a specular surface (the ray finds the exact sub-texel
// hit; the neighbourhood keeps silhouette texels whose centre misses the object) and, for spot lights,
// when it is not entirely outside the cone (photons there carry zero flux: spotAttenuation is 0). Of a
// light with several layers, a layer lists only texels that see an instance it owns (its cluster's), each
// layer into its own segment of the list (layer x mapSize^2), counted per layer for caustics.photonPlan.
#define SCENE_NO_TEXTURES
#define SCENE_NO_TLAS
#include "scene/scene.glsl"
#include "common/emission.h"
#include "caustic_maps/caustic_map.glsl"
#include "caustic_maps/emitter_list.glsl"
#include "caustic_maps/layer_plan.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(set = 1, binding = 0, std430) readonly buffer Maps { CausticMap maps[]; };
layout(set = 1, binding = 1) uniform utexture2DArray mapObjectIds;
layout(set = 1, binding = 2, std430) writeonly buffer Emitters { uint emitters[]; };
layout(set = 1, binding = 3, std430) buffer Plans { CausticLayerPlan plans[]; };
layout(set = 1, binding = 4, std430) buffer Stats { uint stats[]; };
layout(set = 1, binding = 5, std430) readonly buffer Owners { uint owners[]; };
layout(push_constant) uniform Push { uint mapSize; uint instanceCount; } pc;

bool texelIsSpecular(ivec2 t, int layer, CausticMap m) {
    int n = int(pc.mapSize) - 1;
    uint id = texelFetch(mapObjectIds, ivec3(clamp(t, ivec2(0), ivec2(n)), layer), 0).r;
    if (id == 0u || id > pc.instanceCount) return false;
    return sceneMaterialIsSpecular(sceneMaterials[sceneInstances[id - 1u].material]) &&
           CAUSTIC_LAYER_OWNS(owners, m, pc.instanceCount, id - 1u);
}

// Conservative: the texel's centre direction is farther from the spot axis than the outer cone
// angle plus the texel's angular radius (half-diagonal over the distance to the z = 1 plane point).
bool texelOutsideSpotCone(CausticMap m, uvec2 t) {
    if (m.orthographic != 0u || m.cosOuter <= -1.0) return false;
    float n = float(pc.mapSize);
    vec2 q = perspectiveMapPlanePoint(vec2(t) + 0.5, n, m.extent);
    vec3 d = m.forward + q.x * m.right + q.y * m.up;
    float distance = length(d);
    float angularRadius = 1.41421356 * m.extent / n / distance;
    float angle = acos(clamp(dot(d / distance, m.spotAxis), -1.0, 1.0));
    return angle > acos(clamp(m.cosOuter, -1.0, 1.0)) + angularRadius;
}

void main() {
    uvec3 id = gl_GlobalInvocationID;
    if (id.x >= pc.mapSize || id.y >= pc.mapSize) return;
    int layer = int(id.z);
    CausticMap m = maps[layer];
    bool specular = false;
    for (int dy = -1; dy <= 1 && !specular; ++dy)
        for (int dx = -1; dx <= 1 && !specular; ++dx) specular = texelIsSpecular(ivec2(id.xy) + ivec2(dx, dy), layer, m);
    if (!specular || texelOutsideSpotCone(m, id.xy)) return;
    uint slot = atomicAdd(plans[layer].emitters, 1u);
    emitters[uint(layer) * pc.mapSize * pc.mapSize + slot] = packEmitter(id.xy, uint(layer));
    atomicAdd(stats[kStatEmitterTexels], 1u);
}
