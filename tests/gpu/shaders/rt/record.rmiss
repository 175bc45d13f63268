#version 460
#extension GL_EXT_ray_tracing : require
layout(shaderRecordEXT, std430) buffer MissRecord { uint value; };
layout(location = 0) rayPayloadInEXT uint payload;

void main() { payload = value; }
