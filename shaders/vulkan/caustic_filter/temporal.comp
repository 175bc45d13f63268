#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Temporal accumulation (SVGF, Schied et al. 2017, section 4.1; docs/caustics.md "Filter"). The
// pixel's world position goes through last frame's viewProj; of the 2x2 history texels around that
// point, those of the same object with a linear depth (clip w) and normal that agree are blended
// bilinearly (disocclusion test). The history length n (a sample count, capped at maxHistory) makes
// the blend 1/n: until the cap the result is the plain mean of every frame that saw the surface point
// (an unbiased average), then an exponential average with weight 1/maxHistory. The luminance moments
// (l, l^2) accumulate the same way for the variance estimate.
layout(local_size_x = 8, local_size_y = 8) in;
#include "scene/camera.glsl"
#include "caustic_filter/filter_common.glsl"
layout(set = 0, binding = 0) uniform CameraBlock { CameraConstants camera; };
layout(set = 0, binding = 1) uniform texture2D current;
layout(set = 0, binding = 2) uniform texture2D gLinearDepth;
layout(set = 0, binding = 3) uniform texture2D gNormal;
layout(set = 0, binding = 4) uniform utexture2D gObjectId;
layout(set = 0, binding = 5) uniform texture2D historyColor;
layout(set = 0, binding = 6) uniform texture2D historyMoments;   // x E[l], y E[l^2], z n
layout(set = 0, binding = 7) uniform texture2D historyDepth;
layout(set = 0, binding = 8) uniform texture2D historyNormal;
layout(set = 0, binding = 9) uniform utexture2D historyObjectId;
layout(set = 0, binding = 10, rgba32f) uniform writeonly image2D outColor;
layout(set = 0, binding = 11, rgba32f) uniform writeonly image2D outMoments;
layout(push_constant) uniform Push { uint historyValid; float maxHistory; } pc;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(camera.frame.xy);
    if (p.x >= size.x || p.y >= size.y) return;
    vec3 cur = texelFetch(current, p, 0).rgb;
    float l = filterLuminance(cur);
    float depth = texelFetch(gLinearDepth, p, 0).r;
    vec3 n = texelFetch(gNormal, p, 0).xyz;
    uint id = texelFetch(gObjectId, p, 0).r;
    vec3 color = cur;
    vec2 moments = vec2(l, l * l);
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
                if (texelFetch(historyObjectId, q, 0).r != id) continue;
                if (abs(texelFetch(historyDepth, q, 0).r - clip.w) > tolerance) continue;
                if (dot(texelFetch(historyNormal, q, 0).xyz, n) < 0.9) continue;
                float w = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
                hColor += w * texelFetch(historyColor, q, 0).rgb;
                // Per-tap variance, not the moments: mixing the moments of neighbouring texels would add
                // their signal difference (a focal spot's edge) to the variance.
                vec3 m = texelFetch(historyMoments, q, 0).xyz;
                hMoments += w * vec3(m.x, max(0.0, m.y - m.x * m.x), m.z);
                wSum += w;
            }
            if (wSum > 0.01) {
                hColor /= wSum;
                hMoments /= wSum;
                hMoments.y += hMoments.x * hMoments.x;   // back to E[l^2] of the blended history
                historyLength = min(hMoments.z + 1.0, pc.maxHistory);
                float alpha = 1.0 / historyLength;
                color = mix(hColor, cur, alpha);
                moments = mix(hMoments.xy, moments, alpha);
            }
        }
    }
    imageStore(outColor, p, vec4(color, 1.0));
    imageStore(outMoments, p, vec4(moments, historyLength, 0.0));
}
