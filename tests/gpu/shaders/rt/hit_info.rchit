#version 460
#extension GL_EXT_ray_tracing : require
// Reports which instance (its custom index) and which primitive the closest hit was.
layout(location = 0) rayPayloadInEXT uvec2 payload;

void main() {
    payload = uvec2(gl_InstanceCustomIndexEXT, gl_PrimitiveID);
}
