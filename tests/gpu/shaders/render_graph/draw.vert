#version 460
// Pass 2: one triangle from gl_VertexIndex (no vertex buffer), covering part of the target.
const vec2 kPositions[3] = vec2[3](vec2(-0.8, -0.8), vec2(0.8, -0.6), vec2(0.0, 0.9));

void main() {
    gl_Position = vec4(kPositions[gl_VertexIndex], 0.0, 1.0);
}
