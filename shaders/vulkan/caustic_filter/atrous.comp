#version 460
#extension GL_EXT_samplerless_texture_functions : require
// One edge-aware a-trous iteration (Dammertz et al. 2010, "Edge-avoiding a-trous wavelet transform"):
// 5x5 B3-spline kernel with holes of `stepWidth`, weighted by normal similarity, relative depth
// difference and object id equality from the G-buffer.
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0) uniform texture2D inColor;
layout(set = 0, binding = 1) uniform texture2D gLinearDepth;
layout(set = 0, binding = 2) uniform texture2D gNormal;
layout(set = 0, binding = 3) uniform utexture2D gObjectId;
layout(set = 0, binding = 4, rgba32f) uniform writeonly image2D outColor;
layout(push_constant) uniform Push { int stepWidth; int width; int height; int pad; } pc;

const float kKernel[3] = float[](3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0);

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (p.x >= pc.width || p.y >= pc.height) return;
    vec4 centre = texelFetch(inColor, p, 0);
    float z = texelFetch(gLinearDepth, p, 0).r;
    vec3 n = texelFetch(gNormal, p, 0).xyz;
    uint id = texelFetch(gObjectId, p, 0).r;
    if (id == 0u) { imageStore(outColor, p, centre); return; }
    vec3 sum = vec3(0.0);
    float weights = 0.0;
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            ivec2 q = p + ivec2(dx, dy) * pc.stepWidth;
            if (q.x < 0 || q.y < 0 || q.x >= pc.width || q.y >= pc.height) continue;
            if (texelFetch(gObjectId, q, 0).r != id) continue;
            float zq = texelFetch(gLinearDepth, q, 0).r;
            float wz = exp(-abs(zq - z) / (0.01 * z * float(pc.stepWidth) * length(vec2(dx, dy)) + 1e-6));
            float wn = pow(max(0.0, dot(n, texelFetch(gNormal, q, 0).xyz)), 64.0);
            float w = kKernel[abs(dx)] * kKernel[abs(dy)] * wz * wn;
            sum += w * texelFetch(inColor, q, 0).rgb;
            weights += w;
        }
    }
    imageStore(outColor, p, vec4(weights > 0.0 ? sum / weights : centre.rgb, 1.0));
}
