#ifndef CAUSTICS_DIRECT_PAYLOADS_GLSL
#define CAUSTICS_DIRECT_PAYLOADS_GLSL
// Payloads of the direct-lighting state object. Hit group 0 ("surfaceHit") reports which triangle
// was hit; the raygen rebuilds the surface with sceneSurfaceHit(). Miss 0 ("surfaceMiss") leaves
// instance = ~0; miss 1 ("shadowMiss") marks a shadow ray unoccluded.
struct SurfacePayload {
    uint instance;   // ~0u: missed
    uint primitive;
    vec2 barycentrics;
};
const uint kSurfacePayloadLocation = 0;
const uint kShadowPayloadLocation = 1;
#endif
