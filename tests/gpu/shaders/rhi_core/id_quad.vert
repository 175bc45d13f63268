#version 460
// Vertex input: position (RGB32_FLOAT) + object id (R32_UINT), passed through to the fragment stage.
layout(location = 0) in vec3 position;
layout(location = 1) in uint id;
layout(location = 0) flat out uint outId;
void main() {
    outId = id;
    gl_Position = vec4(position, 1.0);
}
