#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// The filter's tile state (docs/caustics.md "Filter", "Tiles"): one 8x8 group per 8x8 pixel tile of the
// view. The state counts the frames a tile's history is kept: keepFrames after a frame in which a photon
// reached one of its pixels, else one less than the largest state among the history texels its pixels
// reproject to (last frame's viewProj, as caustics.temporal does); bit 31 marks "photons this frame".
// tile_list.comp then lists the tiles with a state and their neighbours with photons.
layout(local_size_x = 8, local_size_y = 8) in;
#include "scene/camera.glsl"
#include "caustic_filter/filter_common.glsl"
layout(set = 0, binding = 0) uniform CameraBlock { CameraConstants camera; };
layout(set = 0, binding = 1) uniform texture2D current;          // this frame, unfiltered (caustics.resolve)
layout(set = 0, binding = 2) uniform texture2D gLinearDepth;
layout(set = 0, binding = 3) uniform utexture2D gObjectId;
layout(set = 0, binding = 4) uniform utexture2D previousTiles;   // last frame's tile state
layout(set = 0, binding = 5, r32ui) uniform writeonly uimage2D tileState;
layout(push_constant) uniform Push { uint historyValid; uint keepFrames; } pc;

shared uint sPhotons, sCarried;

// Largest previous tile state among the history texels caustics.temporal may read for a pixel that
// reprojects to `prev`: the 2x2 bilinear taps and the 3x3 around the nearest texel.
uint carriedState(vec2 prev, ivec2 size) {
    ivec2 lo = max(ivec2(floor(prev)) - 1, ivec2(0)), hi = min(ivec2(floor(prev)) + 2, size - 1);
    if (any(greaterThan(lo, hi))) return 0u;
    uint m = 0u;
    for (int ty = lo.y / kFilterTileSize; ty <= hi.y / kFilterTileSize; ++ty)
        for (int tx = lo.x / kFilterTileSize; tx <= hi.x / kFilterTileSize; ++tx)
            m = max(m, texelFetch(previousTiles, ivec2(tx, ty), 0).r & kFilterTileKeepMask);
    return m;
}

void main() {
    if (gl_LocalInvocationIndex == 0u) {
        sPhotons = 0u;
        sCarried = 0u;
    }
    barrier();
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(camera.frame.xy);
    if (p.x < size.x && p.y < size.y) {
        vec3 c = texelFetch(current, p, 0).rgb;
        if (max(c.r, max(c.g, c.b)) > 0.0) atomicOr(sPhotons, 1u);
        float depth = texelFetch(gLinearDepth, p, 0).r;
        if (pc.historyValid != 0u && texelFetch(gObjectId, p, 0).r != 0u && depth > 0.0) {
            vec4 clip = camera.prevViewProj * vec4(cameraWorldPosition(camera, vec2(p) + 0.5, depth), 1.0);
            if (clip.w > 0.0) atomicMax(sCarried, carriedState((clip.xy / clip.w * 0.5 + 0.5) * vec2(size) - 0.5, size));
        }
    }
    barrier();
    if (gl_LocalInvocationIndex == 0u) {
        uint keep = sPhotons != 0u ? (pc.keepFrames | kFilterTilePhotons) : max(sCarried, 1u) - 1u;
        imageStore(tileState, ivec2(gl_WorkGroupID.xy), uvec4(keep));
    }
}
