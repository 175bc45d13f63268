// Shared declarations of the ray-tracing GPU tests: TLAS at set 0 binding 0, one (instance custom
// index, primitive id) pair per ray at binding 1; ~0u marks a miss.
layout(set = 0, binding = 0) uniform accelerationStructureEXT tlas;
layout(set = 0, binding = 1, std430) buffer HitOut { uvec2 hits[]; };
const uint kMiss = 0xFFFFFFFFu;
