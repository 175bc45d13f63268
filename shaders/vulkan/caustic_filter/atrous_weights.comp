#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// First half of one a-trous iteration (docs/caustics.md "Filter"): for every source pixel q, the sum
// W_q of the weights with which it spreads to its 5x5 holed neighbourhood (filterSpreadWeight), and
// its screen-space depth gradient, which the spreading pass reuses. Dividing by W_q at the source (not
// by the sum at the receiver, as SVGF's gather does) keeps the energy exactly: every source hands out
// all of its radiance. (A gather filter loses energy on sparse photon images: a lone photon's pixel
// averages in its dark neighbours, while they take little of it. Measured: 0.55 of the energy kept.)
// Over the listed tiles (tiles.comp); a pixel of an unlisted tile receives nothing (no pass writes it),
// so it is left out of W_q and the energy stays in the listed tiles.
layout(local_size_x = 8, local_size_y = 8) in;
#include "caustic_filter/filter_common.glsl"
layout(set = 0, binding = 0) uniform texture2D inColor;   // rgb radiance, a luminance variance
layout(set = 0, binding = 1) uniform texture2D gLinearDepth;
layout(set = 0, binding = 2) uniform texture2D gNormal;
layout(set = 0, binding = 3) uniform utexture2D gObjectId;
layout(set = 0, binding = 4, rgba32f) uniform writeonly image2D outSource;   // W, dz/dx, dz/dy, 0
layout(set = 0, binding = 5, std430) readonly buffer TileList { uint tiles[]; };
layout(set = 0, binding = 6) uniform utexture2D tileState;   // 0: a tile no filter pass wrote this frame
layout(push_constant) uniform Push { int stepWidth; int width; int height; float sigmaLuminance; } pc;

bool sameSurface(ivec2 q, uint id) {
    return q.x >= 0 && q.y >= 0 && q.x < pc.width && q.y < pc.height && texelFetch(gObjectId, q, 0).r == id;
}

// Screen-space derivative of linear depth along `axis`: the smaller one-sided difference, so a
// neighbour across a depth edge does not make the plane test lenient.
float depthSlope(ivec2 p, ivec2 axis, float z, uint id) {
    float slope = 3.0e38;
    if (sameSurface(p + axis, id)) slope = texelFetch(gLinearDepth, p + axis, 0).r - z;
    if (sameSurface(p - axis, id)) {
        float back = z - texelFetch(gLinearDepth, p - axis, 0).r;
        if (abs(back) < abs(slope)) slope = back;
    }
    return slope < 3.0e38 ? slope : 0.0;
}

void main() {
    ivec2 q = filterTilePixel(tiles[gl_WorkGroupID.x], gl_LocalInvocationID.xy);
    if (q.x >= pc.width || q.y >= pc.height) return;
    uint id = texelFetch(gObjectId, q, 0).r;
    if (id == 0u) { imageStore(outSource, q, vec4(1.0, 0.0, 0.0, 0.0)); return; }
    float z = texelFetch(gLinearDepth, q, 0).r;
    vec3 n = texelFetch(gNormal, q, 0).xyz;
    vec4 c = texelFetch(inColor, q, 0);
    vec2 gradZ = vec2(depthSlope(q, ivec2(1, 0), z, id), depthSlope(q, ivec2(0, 1), z, id));
    float total = 0.0;
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            ivec2 offset = ivec2(dx, dy) * pc.stepWidth;
            ivec2 p = q + offset;
            if (!sameSurface(p, id) || texelFetch(tileState, p / kFilterTileSize, 0).r == 0u) continue;
            vec4 cp = texelFetch(inColor, p, 0);
            total += filterSpreadWeight(offset, pc.stepWidth, z, texelFetch(gLinearDepth, p, 0).r, gradZ, n,
                                        texelFetch(gNormal, p, 0).xyz, filterLuminance(c.rgb),
                                        filterLuminance(cp.rgb), c.a, cp.a, pc.sigmaLuminance);
        }
    }
    // total >= the centre's own weight 9/64 > 0.
    imageStore(outSource, q, vec4(total, gradZ, 0.0));
}
