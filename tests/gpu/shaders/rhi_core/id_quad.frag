#version 460
// Two render targets: a colour per id (RGBA8) and the id itself (R32_UINT).
layout(location = 0) flat in uint id;
layout(location = 0) out vec4 color;
layout(location = 1) out uint idOut;
void main() {
    color = id == 1u ? vec4(1.0, 0.0, 0.0, 1.0) : vec4(0.0, 1.0, 0.0, 1.0);
    idOut = id;
}
