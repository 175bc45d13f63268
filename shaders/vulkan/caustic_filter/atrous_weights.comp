#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// First half of one a-trous iteration (docs/caustics.md "Filter"): for every source pixel q, the sum
// W_q of the weights with which it spreads to its 5x5 holed neighbourhood (filterSpreadWeight), from
// the guides caustics.temporal packed once this frame (depth, its gradient, normal, object id). Dividing by W_q at the source (not
// by the sum at the receiver, as SVGF's gather does) keeps the energy exactly: every source hands out
// all of its radiance. (A gather filter loses energy on sparse photon images: a lone photon's pixel
// averages in its dark neighbours, while they take little of it. Measured: 0.55 of the energy kept.)
// Over the listed tiles (tiles.comp); a pixel of an unlisted tile receives nothing (no pass writes it),
// so it is left out of W_q and the energy stays in the listed tiles.
layout(local_size_x = 8, local_size_y = 8) in;
#include "caustic_filter/filter_common.glsl"
layout(set = 0, binding = 0) uniform texture2D inColor;   // rgb radiance, a luminance variance
layout(set = 0, binding = 1) uniform utexture2D guides;   // filterPackGuide, this frame's
layout(set = 0, binding = 2, r32f) uniform writeonly image2D outSource;   // W
layout(set = 0, binding = 3, std430) readonly buffer TileList { uint tiles[]; };
layout(set = 0, binding = 4) uniform utexture2D tileState;   // 0: a tile no filter pass wrote this frame
layout(push_constant) uniform Push { int stepWidth; int width; int height; float sigmaLuminance; } pc;

void main() {
    ivec2 q = filterTilePixel(tiles[gl_WorkGroupID.x], gl_LocalInvocationID.xy);
    if (q.x >= pc.width || q.y >= pc.height) return;
    FilterGuide gq = filterUnpackGuide(texelFetch(guides, q, 0));
    if (gq.id == 0u) { imageStore(outSource, q, vec4(1.0)); return; }
    vec4 c = texelFetch(inColor, q, 0);
    float total = 0.0;
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            ivec2 offset = ivec2(dx, dy) * pc.stepWidth;
            ivec2 p = q + offset;
            // Pixels of unlisted tiles first: their guides are stale.
            if (p.x < 0 || p.y < 0 || p.x >= pc.width || p.y >= pc.height) continue;
            if (texelFetch(tileState, p / kFilterTileSize, 0).r == 0u) continue;
            FilterGuide gp = filterUnpackGuide(texelFetch(guides, p, 0));
            if (gp.id != gq.id) continue;
            vec4 cp = texelFetch(inColor, p, 0);
            total += filterSpreadWeight(offset, pc.stepWidth, gq.depth, gp.depth, gq.gradZ, gq.normal, gp.normal,
                                        filterLuminance(c.rgb), filterLuminance(cp.rgb), c.a, cp.a, pc.sigmaLuminance);
        }
    }
    // total >= the centre's own weight 9/64 > 0.
    imageStore(outSource, q, vec4(total));
}
