#version 460
// Increments every element once: a small dispatch to time with timestamps.
layout(local_size_x = 64) in;
layout(set = 0, binding = 0, std430) buffer Data { uint values[]; };
void main() { values[gl_GlobalInvocationID.x] += 1u; }
