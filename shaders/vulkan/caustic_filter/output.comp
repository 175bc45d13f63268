#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// With no a-trous iteration the temporal result is the module's radiance: copied, over the listed tiles
// only, into caustics.radiance (whose unlisted tiles hold this frame's zeros; docs/caustics.md "Tiles").
layout(local_size_x = 8, local_size_y = 8) in;
#include "caustic_filter/filter_common.glsl"
layout(set = 0, binding = 0) uniform texture2D temporalColor;
layout(set = 0, binding = 1, std430) readonly buffer TileList { uint tiles[]; };
layout(set = 0, binding = 2, rgba32f) uniform writeonly image2D outColor;
layout(push_constant) uniform Push { int width; int height; } pc;
void main() {
    ivec2 p = filterTilePixel(tiles[gl_WorkGroupID.x], gl_LocalInvocationID.xy);
    if (p.x >= pc.width || p.y >= pc.height) return;
    imageStore(outColor, p, vec4(texelFetch(temporalColor, p, 0).rgb, 1.0));
}
