#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// caustics.specularPixels: the camera pixels whose G-buffer surface is specular (objectId != 0 and
// optics.w >= 0.5), compacted into a list of pixel indices cut at the sphere capacity, and the grid (count, 1, 1) of the backward
// pass's indirect dispatch. caustics.backward then launches once per specular pixel instead of once
// per pixel (docs/caustics.md, "Second-type cost"). Launch (0, 0) also records the sphere TLAS
// capacity the frame was built with (kStatSphereCapacity), for the host's statistics.
#include "backward_trace/sphere_list.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(set = 0, binding = 0) uniform utexture2D gObjectId;
layout(set = 0, binding = 1) uniform texture2D gOptics;
layout(set = 0, binding = 2, std430) writeonly buffer Pixels { uint specularPixels[]; };
layout(set = 0, binding = 3, std430) buffer Args { uint args[]; };   // (width, height, depth) of the backward grid
layout(set = 0, binding = 4, std430) buffer Stats { uint stats[]; };
layout(push_constant) uniform Push { uint width; uint height; uint sphereCapacity; } pc;

void main() {
    uvec2 p = gl_GlobalInvocationID.xy;
    if (p == uvec2(0u)) stats[kStatSphereCapacity] = pc.sphereCapacity;
    if (p.x >= pc.width || p.y >= pc.height) return;
    if (texelFetch(gObjectId, ivec2(p), 0).r == 0u || texelFetch(gOptics, ivec2(p), 0).w < 0.5) return;
    // Every specular pixel is counted (it sizes the next frame's capacity), only those below the
    // capacity are listed: past it there is no sphere slot (caustics/sphere_capacity.h).
    uint slot = atomicAdd(stats[kStatSpecularPixels], 1u);
    if (slot >= pc.sphereCapacity) return;
    specularPixels[slot] = p.y * pc.width + p.x;
    atomicAdd(args[0], 1u);
}
