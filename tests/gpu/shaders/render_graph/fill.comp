#version 460
// Pass 1 of the render-graph GPU test: a deterministic pattern into a storage image.
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, rgba8) uniform writeonly image2D outImage;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(outImage);
    if (any(greaterThanEqual(p, size))) return;
    vec2 uv = vec2(p) / vec2(size - 1);
    float checker = float((p.x ^ p.y) & 8) / 8.0;
    imageStore(outImage, p, vec4(uv.x, uv.y, checker, 1.0));
}
