#ifndef CAUSTICS_D3D12_DIRECT_PAYLOADS_HLSLI
#define CAUSTICS_D3D12_DIRECT_PAYLOADS_HLSLI
// Payloads of the direct-lighting state object (mirror of shaders/vulkan/direct_lighting/payloads.glsl).
// DXR payloads must be structs, so the shadow flag is wrapped.
struct SurfacePayload {
    uint instance;   // ~0u: missed
    uint primitive;
    float2 barycentrics;
};
struct ShadowPayload { uint unoccluded; };
#endif
