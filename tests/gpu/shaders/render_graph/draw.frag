#version 460
// Pass 2: the triangle shows pass 1's pattern (channels swizzled), read as a sampled texture.
layout(set = 0, binding = 0) uniform texture2D pattern;
layout(set = 0, binding = 1) uniform sampler nearestSampler;
layout(location = 0) out vec4 color;

void main() {
    color = texelFetch(sampler2D(pattern, nearestSampler), ivec2(gl_FragCoord.xy), 0).bgra;
}
