// Shared by the rays benchmark's raygen shaders: TLAS, one hit distance per ray (-1 = miss) and the
// per-frame constants.
layout(set = 0, binding = 0) uniform accelerationStructureEXT tlas;
layout(set = 0, binding = 1, std430) buffer HitDistances { float hitT[]; };
layout(push_constant) uniform Frame {
    vec4 cameraPosition;
    vec4 cameraRight;     // scaled by tan(fov / 2) * aspect
    vec4 cameraUp;        // scaled by tan(fov / 2)
    vec4 cameraForward;
    vec4 boundsMin;
    vec4 boundsMax;
    uint frame;
} frameData;

layout(location = 0) rayPayloadEXT float payloadT;
