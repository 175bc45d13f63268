#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Temporal accumulation (SVGF, Schied et al. 2017, section 4.1; docs/caustics.md "Filter"). The
// pixel's world position goes through last frame's viewProj; of the 2x2 history texels around that
// point, those of the same object with a linear depth (clip w) and normal that agree are blended
// bilinearly (disocclusion test). The history length n (a sample count, capped at maxHistory) makes
// the blend 1/n: until the cap the result is the plain mean of every frame that saw the surface point
// (an unbiased average), then an exponential average with weight 1/maxHistory. The luminance moments
// (l, l^2) accumulate the same way for the variance estimate. A history that this frame's photons
// contradict (historyRejected: the caustic moved) is dropped. Dispatched over the tile list (tiles.comp):
// a history texel counts only where last frame's tile state kept it (elsewhere it is stale). The history
// is ping-ponged (docs/caustics.md "Filter", "History"): this pass reads last frame's and writes this
// frame's (the result, before any spatial pass), and packs this frame's guides, so no copy pass follows.
layout(local_size_x = 8, local_size_y = 8) in;
#include "scene/camera.glsl"
#include "caustic_filter/filter_common.glsl"
layout(set = 0, binding = 0) uniform CameraBlock { CameraConstants camera; };
layout(set = 0, binding = 1) uniform texture2D current;
layout(set = 0, binding = 2) uniform texture2D gLinearDepth;
layout(set = 0, binding = 3) uniform texture2D gNormal;
layout(set = 0, binding = 4) uniform utexture2D gObjectId;
layout(set = 0, binding = 5) uniform texture2D historyColor;     // rgb mean, a history length n
layout(set = 0, binding = 6) uniform texture2D historyMoments;   // r E[l^2] (E[l] = luminance of the mean)
layout(set = 0, binding = 7) uniform utexture2D historyGuides;   // filterPackGuide
layout(set = 0, binding = 8) uniform utexture2D previousTiles;   // 0: the history texels there are stale
layout(set = 0, binding = 9, std430) readonly buffer TileList { uint tiles[]; };
layout(set = 0, binding = 10, rgba32f) uniform writeonly image2D outColor;
layout(set = 0, binding = 11, r32f) uniform writeonly image2D outMoments;
layout(set = 0, binding = 12, rgba32ui) uniform writeonly uimage2D outGuides;
layout(push_constant) uniform Push { uint historyValid; float maxHistory; } pc;

const float kHistoryRejectDeviations = 3.0;
const float kTrustedHistory = 4.0;   // SVGF's threshold for trusting the temporal moments

bool historyKept(ivec2 q) { return texelFetch(previousTiles, q / kFilterTileSize, 0).r != 0u; }

// E[l], E[l^2], n of a history texel.
vec3 historyMomentsAt(ivec2 q) {
    vec4 c = texelFetch(historyColor, q, 0);
    return vec3(filterLuminance(c.rgb), texelFetch(historyMoments, q, 0).r, c.a);
}

// True when this frame's caustic around p is inconsistent with the history (the caustic moved: a light
// or an object moved, which the camera reprojection cannot follow; docs/caustics.md "Filter", "Moving
// caustics"). Compares the 3x3 sums of this frame's luminance C and of the history's mean H over the
// same taps (history texels nearest to the reprojected point, offset alike), taps of this object only.
// Under "nothing changed", C - H has the variance of one frame's 3x3 sum, the sum of the taps' per-frame
// variances V (temporal moments; for a compound-Poisson photon sum V = q_eff E[l], so no photon quantum
// has to be guessed). Rejected when |C - H| > 3 sqrt(sum V) + 2 q, q the smallest non-zero luminance of
// this frame in the 3x3 (one photon): a caustic of ~1 photon per pixel per frame that leaves a pixel
// is caught in one frame, 3 photons where the history was dark start a new one; stray photons do not.
bool historyRejected(ivec2 p, ivec2 nearest, ivec2 size, uint id) {
    float c = 0.0, h = 0.0, v = 0.0, quantum = 0.0;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 q = p + ivec2(dx, dy), hq = nearest + ivec2(dx, dy);
            if (any(lessThan(min(q, hq), ivec2(0))) || any(greaterThanEqual(max(q, hq), size))) continue;
            if (texelFetch(gObjectId, q, 0).r != id || !historyKept(hq) || texelFetch(historyGuides, hq, 0).w != id)
                continue;
            float l = filterLuminance(texelFetch(current, q, 0).rgb);
            vec3 m = historyMomentsAt(hq);
            c += l;
            h += m.x;
            v += max(0.0, m.y - m.x * m.x);
            if (l > 0.0) quantum = quantum > 0.0 ? min(quantum, l) : l;
        }
    }
    return abs(c - h) > kHistoryRejectDeviations * sqrt(v) + 2.0 * quantum;
}

bool sameSurface(ivec2 q, ivec2 size, uint id) {
    return all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, size)) && texelFetch(gObjectId, q, 0).r == id;
}

// Screen-space derivative of linear depth along `axis`: the smaller one-sided difference, so a
// neighbour across a depth edge does not make the a-trous plane test lenient. Once per frame, here.
float depthSlope(ivec2 p, ivec2 axis, ivec2 size, float z, uint id) {
    float slope = 3.0e38;
    if (sameSurface(p + axis, size, id)) slope = texelFetch(gLinearDepth, p + axis, 0).r - z;
    if (sameSurface(p - axis, size, id)) {
        float back = z - texelFetch(gLinearDepth, p - axis, 0).r;
        if (abs(back) < abs(slope)) slope = back;
    }
    return slope < 3.0e38 ? slope : 0.0;
}

void main() {
    ivec2 p = filterTilePixel(tiles[gl_WorkGroupID.x], gl_LocalInvocationID.xy);
    ivec2 size = ivec2(camera.frame.xy);
    if (p.x >= size.x || p.y >= size.y) return;
    vec3 cur = texelFetch(current, p, 0).rgb;
    float l = filterLuminance(cur);
    float depth = texelFetch(gLinearDepth, p, 0).r;
    vec3 n = texelFetch(gNormal, p, 0).xyz;
    uint id = texelFetch(gObjectId, p, 0).r;
    vec3 color = cur;
    float moment2 = l * l;
    float historyLength = 1.0;
    if (pc.historyValid != 0u && id != 0u && depth > 0.0) {
        vec3 world = cameraWorldPosition(camera, vec2(p) + 0.5, depth);
        vec4 clip = camera.prevViewProj * vec4(world, 1.0);
        if (clip.w > 0.0) {
            vec2 prev = (clip.xy / clip.w * 0.5 + 0.5) * vec2(size) - 0.5;   // texel-centre coordinates
            ivec2 base = ivec2(floor(prev));
            vec2 f = prev - vec2(base);
            float tolerance = clip.w * filterRelativeDepthTolerance(camera.forward.w, float(size.y), n,
                                                                   normalize(camera.eye.xyz - world));
            vec3 hColor = vec3(0.0), hMoments = vec3(0.0);
            float wSum = 0.0;
            for (int i = 0; i < 4; ++i) {
                ivec2 o = ivec2(i & 1, i >> 1);
                ivec2 q = base + o;
                if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
                if (!historyKept(q)) continue;
                FilterGuide hg = filterUnpackGuide(texelFetch(historyGuides, q, 0));
                if (hg.id != id) continue;
                if (abs(hg.depth - clip.w) > tolerance) continue;
                if (dot(hg.normal, n) < 0.9) continue;
                float w = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
                hColor += w * texelFetch(historyColor, q, 0).rgb;
                // Per-tap variance, not the moments: mixing the moments of neighbouring texels would add
                // their signal difference (a focal spot's edge) to the variance.
                vec3 m = historyMomentsAt(q);
                hMoments += w * vec3(m.x, max(0.0, m.y - m.x * m.x), m.z);
                wSum += w;
            }
            // The test needs variances from the moments: histories shorter than kTrustedHistory frames
            // are short already (their lag is at most that long).
            bool rejected = wSum > 0.01 && hMoments.z / wSum >= kTrustedHistory &&
                            historyRejected(p, ivec2(floor(prev + 0.5)), size, id);
            if (wSum > 0.01 && !rejected) {
                hColor /= wSum;
                hMoments /= wSum;
                hMoments.y += hMoments.x * hMoments.x;   // back to E[l^2] of the blended history
                historyLength = min(hMoments.z + 1.0, pc.maxHistory);
                float alpha = 1.0 / historyLength;
                color = mix(hColor, cur, alpha);
                moment2 = mix(hMoments.y, moment2, alpha);
            }
        }
    }
    vec2 gradZ = vec2(depthSlope(p, ivec2(1, 0), size, depth, id), depthSlope(p, ivec2(0, 1), size, depth, id));
    imageStore(outColor, p, vec4(color, historyLength));
    imageStore(outMoments, p, vec4(moment2));
    imageStore(outGuides, p, filterPackGuide(depth, gradZ, n, id));
}
