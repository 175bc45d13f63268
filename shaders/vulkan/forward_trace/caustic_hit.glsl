#ifndef CAUSTICS_CAUSTIC_HIT_GLSL
#define CAUSTICS_CAUSTIC_HIT_GLSL
// std430 mirrors of caustics::CausticHit / CausticSphere (passes/include/caustics/caustic_passes.h)
// and the statistics slots.
struct CausticHit {
    vec3 position; uint objectId;
    vec3 normal;   uint light;       // normal: unit, on the side the photon arrived from
    vec3 fluxBsdf; float pad;        // flux x Lambert BRDF
};
struct CausticSphere {
    vec3 centre;        float radius;   // radius 0: no sphere
    vec3 transmittance; uint objectId;
    vec3 normal;        uint pixel;
};
const uint kStatStoredHitAttempts = 0u;
const uint kStatSplats = 1u;
const uint kStatGatherHits = 2u;
const uint kStatSpheres = 3u;
const uint kStatRaysPerLight = 4u;

// Closest-hit payload of trace.rchit / trace.rmiss: t < 0 = miss.
struct TracePayload {
    vec2 barycentrics;
    uint instance;
    uint primitive;
    float t;
};

// Surface offset for continuing rays, relative to the coordinates' magnitude (float spacing).
float rayEpsilon(vec3 p) { return 1e-4 * (1.0 + max(abs(p.x), max(abs(p.y), abs(p.z)))); }
#endif
