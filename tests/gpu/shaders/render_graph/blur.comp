#version 460
// Pass 3: 3x3 box blur of pass 2's render target (sampled) into a storage image.
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0) uniform texture2D source;
layout(set = 0, binding = 1) uniform sampler nearestSampler;
layout(set = 0, binding = 2, rgba8) uniform writeonly image2D outImage;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(outImage);
    if (any(greaterThanEqual(p, size))) return;
    vec4 sum = vec4(0.0);
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            sum += texelFetch(sampler2D(source, nearestSampler), clamp(p + ivec2(dx, dy), ivec2(0), size - 1), 0);
    imageStore(outImage, p, sum / 9.0);
}
