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
// a history texel exists only where last frame's slot map gave its tile a pool tile. The history is
// ping-ponged (docs/caustics.md "Filter", "History"): this pass reads last frame's pool and writes this
// frame's (the result, before any spatial pass, and its guides), so no copy pass follows; and the depth
// gradient the a-trous passes use, once per frame. Everything in the pool is pre-exposed half precision.
layout(local_size_x = 8, local_size_y = 8) in;
#include "scene/camera.glsl"
#include "caustic_filter/filter_common.glsl"
layout(set = 0, binding = 0) uniform CameraBlock { CameraConstants camera; };
layout(set = 0, binding = 1) uniform texture2D current;          // this frame, unfiltered (screen)
layout(set = 0, binding = 2) uniform texture2D gLinearDepth;
layout(set = 0, binding = 3) uniform texture2D gNormal;
layout(set = 0, binding = 4) uniform utexture2D gObjectId;
// Last frame's history (pool, filter_common.glsl): rgb mean x last frame's pre-exposure, a the
// per-frame standard deviation of luminance, same units; the guides hold depth, n, normal, id.
layout(set = 0, binding = 5) uniform texture2D historyColor;
layout(set = 0, binding = 6) uniform utexture2D historyGuides;
layout(set = 0, binding = 7) uniform utexture2D previousSlots;   // last frame's slot map
layout(set = 0, binding = 8, std430) readonly buffer TileList { uint tiles[]; };
layout(set = 0, binding = 9, rgba16f) uniform writeonly image2D outColor;     // this frame's, pool
layout(set = 0, binding = 10, rg32ui) uniform writeonly uimage2D outGuides;   // this frame's, pool
layout(set = 0, binding = 11, r32ui) uniform writeonly uimage2D outGradient;  // half2 depth slope, pool
// preExposure: this frame's (the host's exposure, docs/caustics.md "Filter", "Memory"); historyScale:
// this frame's over last frame's, which the history was stored with.
// motionGuides: gLinearDepth is the second type's guide (depth, motion x, motion y, last frame's depth;
// docs/caustics.md "Second-type guides"): reproject with the receiver's own motion, not the camera ray's.
layout(push_constant) uniform Push { uint historyValid; float maxHistory; float preExposure; float historyScale; uint motionGuides; } pc;

const float kHistoryRejectDeviations = 3.0;
const float kTrustedHistory = 4.0;   // SVGF's threshold for trusting the temporal moments

// Last frame's pool texel of screen texel q, or (-1, -1) where its tile kept no history.
ivec2 historyTexel(ivec2 q) {
    uint slot = texelFetch(previousSlots, q / kFilterTileSize, 0).r;
    return slot == kFilterNoSlot ? ivec2(-1) : filterPoolTexel(slot, filterLocal(q));
}

// E[l], per-frame variance of l, n of a history texel (this frame's pre-exposed units).
vec3 historyMomentsAt(ivec2 h, FilterGuide g) {
    vec4 c = texelFetch(historyColor, h, 0) * pc.historyScale;
    return vec3(filterLuminance(c.rgb), c.a * c.a, g.historyLength);
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
            if (texelFetch(gObjectId, q, 0).r != id) continue;
            ivec2 ht = historyTexel(hq);
            if (ht.x < 0) continue;
            FilterGuide g = filterUnpackGuide(texelFetch(historyGuides, ht, 0).rg);
            if (g.id != filterGuideId(id)) continue;
            float l = filterLuminance(texelFetch(current, q, 0).rgb * pc.preExposure);
            vec3 m = historyMomentsAt(ht, g);
            c += l;
            h += m.x;
            v += m.y;
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
    ivec2 pool = filterPoolTexel(gl_WorkGroupID.x, ivec2(gl_LocalInvocationID.xy));
    vec3 cur = texelFetch(current, p, 0).rgb * pc.preExposure;
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
        vec4 guide = texelFetch(gLinearDepth, p, 0);
        if (pc.motionGuides != 0u) clip.w = guide.w;
        if (clip.w > 0.0) {
            // Texel-centre coordinates.
            vec2 prev = pc.motionGuides != 0u ? vec2(p) + guide.yz : (clip.xy / clip.w * 0.5 + 0.5) * vec2(size) - 0.5;
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
                ivec2 ht = historyTexel(q);
                if (ht.x < 0) continue;
                FilterGuide hg = filterUnpackGuide(texelFetch(historyGuides, ht, 0).rg);
                if (hg.id != filterGuideId(id)) continue;
                if (abs(hg.depth - clip.w) > tolerance) continue;
                if (dot(hg.normal, n) < 0.9) continue;
                float w = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
                hColor += w * texelFetch(historyColor, ht, 0).rgb * pc.historyScale;
                // Per-tap variance, not the moments: mixing the moments of neighbouring texels would add
                // their signal difference (a focal spot's edge) to the variance.
                hMoments += w * historyMomentsAt(ht, hg);
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
    // The variance leaves here as a standard deviation: E[l^2] - E[l]^2 cancels in 32 bits, and the
    // deviation has the range of the radiance, which half precision holds (docs/caustics.md "Memory").
    float lm = filterLuminance(color);
    float deviation = sqrt(max(0.0, moment2 - lm * lm));
    vec2 gradZ = vec2(depthSlope(p, ivec2(1, 0), size, depth, id), depthSlope(p, ivec2(0, 1), size, depth, id));
    imageStore(outColor, pool, filterNearestHalf(vec4(color, deviation)));
    imageStore(outGuides, pool, uvec4(filterPackGuide(depth, historyLength, n, id), 0u, 0u));
    imageStore(outGradient, pool, uvec4(packHalf2x16(gradZ)));
}
