#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// With no a-trous iteration the temporal result is the module's radiance: written, over the listed tiles
// only, into caustics.radiance (whose unlisted tiles hold this frame's zeros; docs/caustics.md "Tiles").
// A pixel without history (n = 1) keeps this frame's radiance as it is: the temporal result is that
// frame, and the pool's pre-exposed half precision would only round it.
layout(local_size_x = 8, local_size_y = 8) in;
#include "caustic_filter/filter_common.glsl"
layout(set = 0, binding = 0) uniform texture2D temporalColor;   // pool
layout(set = 0, binding = 1) uniform utexture2D temporalGuides; // pool: n
layout(set = 0, binding = 2, std430) readonly buffer TileList { uint tiles[]; };
layout(set = 0, binding = 3, rgba32f) uniform image2D radiance;  // this frame's, replaced in place
layout(push_constant) uniform Push { int width; int height; float invPreExposure; } pc;
void main() {
    ivec2 p = filterTilePixel(tiles[gl_WorkGroupID.x], gl_LocalInvocationID.xy);
    if (p.x >= pc.width || p.y >= pc.height) return;
    ivec2 own = filterPoolTexel(gl_WorkGroupID.x, ivec2(gl_LocalInvocationID.xy));
    if (filterUnpackGuide(texelFetch(temporalGuides, own, 0).rg).historyLength <= 1.0) return;
    imageStore(radiance, p, vec4(texelFetch(temporalColor, own, 0).rgb * pc.invPreExposure, 1.0));
}
