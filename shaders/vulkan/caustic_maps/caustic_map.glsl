#ifndef CAUSTICS_CAUSTIC_MAP_GLSL
#define CAUSTICS_CAUSTIC_MAP_GLSL
// std430 mirror of caustics::CausticMapGpu (passes/include/caustics/caustic_map_plan.h), 160 bytes.
struct CausticMap {
    vec3 origin;   uint light;
    vec3 right;    float extent;        // perspective: tan(half-angle); orthographic: half-extent
    vec3 up;       uint orthographic;
    vec3 forward;  float nearPlane;
    vec3 intensity; float cosInner;
    vec3 spotAxis; float cosOuter;      // cosOuter <= -1: no cone
    mat4 viewProj;
};
#endif
