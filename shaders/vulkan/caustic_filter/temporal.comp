#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
// Temporal accumulation with reprojection (paper 3.4): the pixel's world position goes through last
// frame's viewProj; the history sample is kept only for the same object, a linear depth within 2 %
// (clip w of the previous view = its linear depth) and a normal within ~25 degrees.
layout(local_size_x = 8, local_size_y = 8) in;
#include "scene/camera.glsl"
layout(set = 0, binding = 0) uniform CameraBlock { CameraConstants camera; };
layout(set = 0, binding = 1) uniform texture2D current;
layout(set = 0, binding = 2) uniform texture2D gLinearDepth;
layout(set = 0, binding = 3) uniform texture2D gNormal;
layout(set = 0, binding = 4) uniform utexture2D gObjectId;
layout(set = 0, binding = 5) uniform texture2D historyColor;
layout(set = 0, binding = 6) uniform texture2D historyDepth;
layout(set = 0, binding = 7) uniform texture2D historyNormal;
layout(set = 0, binding = 8) uniform utexture2D historyObjectId;
layout(set = 0, binding = 9, rgba32f) uniform writeonly image2D outColor;
layout(push_constant) uniform Push { float alpha; uint historyValid; } pc;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(camera.frame.xy);
    if (p.x >= size.x || p.y >= size.y) return;
    vec4 cur = texelFetch(current, p, 0);
    float depth = texelFetch(gLinearDepth, p, 0).r;
    uint id = texelFetch(gObjectId, p, 0).r;
    vec4 result = cur;
    if (pc.historyValid != 0u && id != 0u && depth > 0.0) {
        vec3 world = cameraWorldPosition(camera, vec2(p) + 0.5, depth);
        vec4 clip = camera.prevViewProj * vec4(world, 1.0);
        if (clip.w > 0.0) {
            vec2 prev = (clip.xy / clip.w * 0.5 + 0.5) * vec2(size);
            ivec2 q = ivec2(floor(prev));
            if (all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, size))) {
                bool sameObject = texelFetch(historyObjectId, q, 0).r == id;
                bool depthOk = abs(texelFetch(historyDepth, q, 0).r - clip.w) <= 0.02 * clip.w;
                bool normalOk = dot(texelFetch(historyNormal, q, 0).xyz, texelFetch(gNormal, p, 0).xyz) > 0.9;
                if (sameObject && depthOk && normalOk) result = mix(texelFetch(historyColor, q, 0), cur, pc.alpha);
            }
        }
    }
    imageStore(outColor, p, result);
}
