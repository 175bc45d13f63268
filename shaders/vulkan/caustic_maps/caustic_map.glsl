#ifndef CAUSTICS_CAUSTIC_MAP_GLSL
#define CAUSTICS_CAUSTIC_MAP_GLSL
// std430 mirror of caustics::CausticMapGpu (passes/include/caustics/caustic_map_plan.h), 176 bytes.
struct CausticMap {
    vec3 origin;   uint light;
    vec3 right;    float extent;        // perspective: tan(half-angle); orthographic: half-extent
    vec3 up;       uint orthographic;
    vec3 forward;  float nearPlane;
    vec3 intensity; float cosInner;
    vec3 spotAxis; float cosOuter;      // cosOuter <= -1: no cone
    mat4 viewProj;
    float range;                        // KHR_lights_punctual range, 0 = infinite
    float photons;                      // this layer's photons per frame; 0: raysPerTexel per texel
    uint cluster;                       // the layer's number among its light's layers
    uint ownerRow;                      // row of the instance -> layer ownership table
};

// Does layer m own scene instance `instance` (its cluster holds it)? `owners` rows have instanceCount
// entries: cluster + 1 of the owning layer of that light, 0 for none (caustic_map_plan.h).
#define CAUSTIC_LAYER_OWNS(owners, m, instanceCount, instance) \
    (owners[(m).ownerRow * (instanceCount) + (instance)] == (m).cluster + 1u)
#endif
