#version 460
#extension GL_EXT_samplerless_texture_functions : require
#extension GL_GOOGLE_include_directive : require
// Keeps this frame's temporal accumulation (before any spatial filtering, so the history stays an
// unbiased average), its luminance moments and history length, and the G-buffer guides that the next
// frame's disocclusion test compares against. Over the listed tiles only (tiles.comp): elsewhere the
// history keeps stale texels, which the tile state marks.
layout(local_size_x = 8, local_size_y = 8) in;
#include "caustic_filter/filter_common.glsl"
layout(set = 0, binding = 0) uniform texture2D temporalColor;
layout(set = 0, binding = 1) uniform texture2D temporalMoments;
layout(set = 0, binding = 2) uniform texture2D gLinearDepth;
layout(set = 0, binding = 3) uniform texture2D gNormal;
layout(set = 0, binding = 4) uniform utexture2D gObjectId;
layout(set = 0, binding = 5, rgba32f) uniform writeonly image2D historyColor;
layout(set = 0, binding = 6, rgba32f) uniform writeonly image2D historyMoments;
layout(set = 0, binding = 7, r32f) uniform writeonly image2D historyDepth;
layout(set = 0, binding = 8, rgba16f) uniform writeonly image2D historyNormal;
layout(set = 0, binding = 9, r32ui) uniform writeonly uimage2D historyObjectId;
layout(set = 0, binding = 10, std430) readonly buffer TileList { uint tiles[]; };
layout(push_constant) uniform Push { int width; int height; } pc;
void main() {
    ivec2 p = filterTilePixel(tiles[gl_WorkGroupID.x], gl_LocalInvocationID.xy);
    if (p.x >= pc.width || p.y >= pc.height) return;
    imageStore(historyColor, p, texelFetch(temporalColor, p, 0));
    imageStore(historyMoments, p, texelFetch(temporalMoments, p, 0));
    imageStore(historyDepth, p, vec4(texelFetch(gLinearDepth, p, 0).r));
    imageStore(historyNormal, p, texelFetch(gNormal, p, 0));
    imageStore(historyObjectId, p, uvec4(texelFetch(gObjectId, p, 0).r));
}
