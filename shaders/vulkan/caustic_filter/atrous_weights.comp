#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// First half of one a-trous iteration (docs/caustics.md "Filter"): for every source pixel q, the sum
// W_q of the weights with which it spreads to its 5x5 holed neighbourhood (filterSpreadWeight), from this
// frame's G-buffer (depth, normal, object id) and the depth gradient caustics.temporal computed once.
// Dividing by W_q at the source (not by the sum at the receiver, as SVGF's gather does) keeps the energy
// exactly: every source hands out all of its radiance. (A gather filter loses energy on sparse photon
// images: a lone photon's pixel averages in its dark neighbours, while they take little of it. Measured:
// 0.55 of the energy kept.) Over the listed tiles (tiles.comp); a pixel of a tile without a pool tile
// receives nothing (no pass writes it), so it is left out of W_q and the energy stays in the listed tiles.
layout(local_size_x = 8, local_size_y = 8) in;
#include "caustic_filter/filter_common.glsl"
layout(set = 0, binding = 0) uniform texture2D inColor;   // pool: rgb radiance, a deviation of the mean
layout(set = 0, binding = 1) uniform texture2D gLinearDepth;
layout(set = 0, binding = 2) uniform texture2D gNormal;
layout(set = 0, binding = 3) uniform utexture2D gObjectId;
layout(set = 0, binding = 4) uniform utexture2D gradient;   // pool: half2 depth slope (caustics.temporal)
layout(set = 0, binding = 5) uniform utexture2D slotMap;    // this frame's
layout(set = 0, binding = 6, std430) readonly buffer TileList { uint tiles[]; };
layout(set = 0, binding = 7, r32f) uniform writeonly image2D outSource;   // pool: W
layout(push_constant) uniform Push { int stepWidth; int width; int height; float sigmaLuminance; } pc;

void main() {
    ivec2 q = filterTilePixel(tiles[gl_WorkGroupID.x], gl_LocalInvocationID.xy);
    if (q.x >= pc.width || q.y >= pc.height) return;
    ivec2 own = filterPoolTexel(gl_WorkGroupID.x, ivec2(gl_LocalInvocationID.xy));
    uint id = texelFetch(gObjectId, q, 0).r;
    if (id == 0u) { imageStore(outSource, own, vec4(1.0)); return; }
    vec4 c = texelFetch(inColor, own, 0);
    float zq = texelFetch(gLinearDepth, q, 0).r;
    vec3 nq = texelFetch(gNormal, q, 0).xyz;
    vec2 gradZq = unpackHalf2x16(texelFetch(gradient, own, 0).r);
    float total = 0.0;
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            ivec2 offset = ivec2(dx, dy) * pc.stepWidth;
            ivec2 p = q + offset;
            // Pixels of tiles without a pool tile first: nothing is written there.
            if (p.x < 0 || p.y < 0 || p.x >= pc.width || p.y >= pc.height) continue;
            uint slot = texelFetch(slotMap, p / kFilterTileSize, 0).r;
            if (slot == kFilterNoSlot) continue;
            if (texelFetch(gObjectId, p, 0).r != id) continue;
            vec4 cp = texelFetch(inColor, filterPoolTexel(slot, filterLocal(p)), 0);
            total += filterSpreadWeight(offset, pc.stepWidth, zq, texelFetch(gLinearDepth, p, 0).r, gradZq, nq,
                                        texelFetch(gNormal, p, 0).xyz, filterLuminance(c.rgb),
                                        filterLuminance(cp.rgb), c.a * c.a, cp.a * cp.a, pc.sigmaLuminance);
        }
    }
    // total >= the centre's own weight 9/64 > 0.
    imageStore(outSource, own, vec4(total));
}
