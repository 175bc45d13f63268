#version 460
// Light-space G-buffer: world position (w = 1 where covered), outward shading normal, objectId
// (instance index + 1; 0 = empty). The trace reads the material through the instance.
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) flat in uint inInstance;

layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out uint outObjectId;

void main() {
    outPosition = vec4(inPosition, 1.0);
    outNormal = vec4(normalize(inNormal), 0.0);
    outObjectId = inInstance + 1u;
}
