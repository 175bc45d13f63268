// Second half of one a-trous iteration (Dammertz et al. 2010 with SVGF's edge-stopping weights,
// Schied et al. 2017; docs/caustics.md "Filter"): pixel p receives from every source q of its 5x5
// holed neighbourhood the share w(q -> p) / W_q of q's radiance (atrous_weights.comp computed W_q from
// this frame's G-buffer and the depth gradient). Luminance differences larger than q's noise stop the
// spreading, so a caustic's focal spot and fold lines keep their shape; the shares of a source add up
// to 1, so the energy is kept. The variance goes along: Var_p = sum (w / W_q)^2 Var_q (stored as its
// square root). Over the listed tiles (tiles.comp); sources in tiles without a pool tile are skipped
// (nothing wrote them; atrous_weights.comp left those pixels out of W_q alike). atrous.comp writes the
// pool; atrous_last.comp (kAtrousLast) writes caustics.radiance itself, back in radiance units (the
// pool is pre-exposed), whose unlisted tiles hold this frame's zeros.
layout(local_size_x = 8, local_size_y = 8) in;
#include "caustic_filter/filter_common.glsl"
layout(set = 0, binding = 0) uniform texture2D inColor;   // pool: rgb radiance, a deviation of the mean
layout(set = 0, binding = 1) uniform texture2D sources;   // pool: W per source
layout(set = 0, binding = 2) uniform texture2D gLinearDepth;
layout(set = 0, binding = 3) uniform texture2D gNormal;
layout(set = 0, binding = 4) uniform utexture2D gObjectId;
layout(set = 0, binding = 5) uniform utexture2D gradient;   // pool: half2 depth slope
layout(set = 0, binding = 6) uniform utexture2D slotMap;    // this frame's
layout(set = 0, binding = 7, std430) readonly buffer TileList { uint tiles[]; };
#if defined(kAtrousLast)
layout(set = 0, binding = 8, rgba32f) uniform writeonly image2D outColor;   // screen: caustics.radiance
#else
layout(set = 0, binding = 8, rgba16f) uniform writeonly image2D outColor;   // pool
#endif
layout(push_constant) uniform Push {
    int stepWidth;
    int width;
    int height;
    float sigmaLuminance;
    float invPreExposure;   // atrous_last.comp: pool units -> radiance
} pc;

void store(ivec2 p, ivec2 own, vec3 rgb, float deviation) {
#if defined(kAtrousLast)
    imageStore(outColor, p, vec4(rgb * pc.invPreExposure, 1.0));
#else
    imageStore(outColor, own, filterNearestHalf(vec4(rgb, deviation)));
#endif
}

void main() {
    ivec2 p = filterTilePixel(tiles[gl_WorkGroupID.x], gl_LocalInvocationID.xy);
    if (p.x >= pc.width || p.y >= pc.height) return;
    ivec2 own = filterPoolTexel(gl_WorkGroupID.x, ivec2(gl_LocalInvocationID.xy));
    vec4 centre = texelFetch(inColor, own, 0);
    uint id = texelFetch(gObjectId, p, 0).r;
    if (id == 0u) {
        store(p, own, centre.rgb, centre.a);
        return;
    }
    float zp = texelFetch(gLinearDepth, p, 0).r;
    vec3 np = texelFetch(gNormal, p, 0).xyz;
    float lp = filterLuminance(centre.rgb);
    vec3 sum = vec3(0.0);
    float variance = 0.0;
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            ivec2 q = p + ivec2(dx, dy) * pc.stepWidth;
            if (q.x < 0 || q.y < 0 || q.x >= pc.width || q.y >= pc.height) continue;
            uint slot = texelFetch(slotMap, q / kFilterTileSize, 0).r;
            if (slot == kFilterNoSlot) continue;
            if (texelFetch(gObjectId, q, 0).r != id) continue;
            ivec2 t = filterPoolTexel(slot, filterLocal(q));
            vec4 c = texelFetch(inColor, t, 0);
            vec2 gradZq = unpackHalf2x16(texelFetch(gradient, t, 0).r);
            float share = filterSpreadWeight(p - q, pc.stepWidth, texelFetch(gLinearDepth, q, 0).r, zp, gradZq,
                                             texelFetch(gNormal, q, 0).xyz, np, filterLuminance(c.rgb), lp,
                                             c.a * c.a, centre.a * centre.a, pc.sigmaLuminance) /
                          texelFetch(sources, t, 0).r;
            sum += share * c.rgb;
            variance += share * share * c.a * c.a;
        }
    }
    store(p, own, sum, sqrt(variance));
}
