#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Second half of one a-trous iteration (Dammertz et al. 2010 with SVGF's edge-stopping weights,
// Schied et al. 2017; docs/caustics.md "Filter"): pixel p receives from every source q of its 5x5
// holed neighbourhood the share w(q -> p) / W_q of q's radiance (atrous_weights.comp computed W_q; the
// guides are this frame's, packed by caustics.temporal).
// Luminance differences larger than q's noise stop the spreading, so a caustic's focal spot and fold
// lines keep their shape; the shares of a source add up to 1, so the energy is kept. The variance
// goes along: Var_p = sum (w / W_q)^2 Var_q. Over the listed tiles (tiles.comp); sources in unlisted
// tiles are skipped (nothing wrote them; atrous_weights.comp left those pixels out of W_q alike). The
// last iteration writes caustics.radiance itself, whose unlisted tiles hold this frame's zeros.
layout(local_size_x = 8, local_size_y = 8) in;
#include "caustic_filter/filter_common.glsl"
layout(set = 0, binding = 0) uniform texture2D inColor;   // rgb radiance, a luminance variance
layout(set = 0, binding = 1) uniform texture2D sources;   // W per source
layout(set = 0, binding = 2) uniform utexture2D guides;   // filterPackGuide, this frame's
layout(set = 0, binding = 3, rgba32f) uniform writeonly image2D outColor;
layout(set = 0, binding = 4, std430) readonly buffer TileList { uint tiles[]; };
layout(set = 0, binding = 5) uniform utexture2D tileState;   // 0: a tile no filter pass wrote this frame
layout(push_constant) uniform Push {
    int stepWidth;
    int width;
    int height;
    float sigmaLuminance;
    uint lastIteration;   // 1: write alpha 1 (the module's radiance output), not the variance
} pc;

void main() {
    ivec2 p = filterTilePixel(tiles[gl_WorkGroupID.x], gl_LocalInvocationID.xy);
    if (p.x >= pc.width || p.y >= pc.height) return;
    vec4 centre = texelFetch(inColor, p, 0);
    FilterGuide gp = filterUnpackGuide(texelFetch(guides, p, 0));
    if (gp.id == 0u) {
        imageStore(outColor, p, vec4(centre.rgb, pc.lastIteration != 0u ? 1.0 : centre.a));
        return;
    }
    float lp = filterLuminance(centre.rgb);
    vec3 sum = vec3(0.0);
    float variance = 0.0;
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            ivec2 q = p + ivec2(dx, dy) * pc.stepWidth;
            if (q.x < 0 || q.y < 0 || q.x >= pc.width || q.y >= pc.height) continue;
            if (texelFetch(tileState, q / kFilterTileSize, 0).r == 0u) continue;
            FilterGuide gq = filterUnpackGuide(texelFetch(guides, q, 0));
            if (gq.id != gp.id) continue;
            vec4 c = texelFetch(inColor, q, 0);
            float share = filterSpreadWeight(p - q, pc.stepWidth, gq.depth, gp.depth, gq.gradZ, gq.normal, gp.normal,
                                             filterLuminance(c.rgb), lp, c.a, centre.a, pc.sigmaLuminance) /
                          texelFetch(sources, q, 0).r;
            sum += share * c.rgb;
            variance += share * share * c.a;
        }
    }
    imageStore(outColor, p, vec4(sum, pc.lastIteration != 0u ? 1.0 : variance));
}
