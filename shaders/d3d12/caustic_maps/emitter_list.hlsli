#ifndef CAUSTICS_D3D12_EMITTER_LIST_HLSLI
#define CAUSTICS_D3D12_EMITTER_LIST_HLSLI
// Mirror of shaders/vulkan/caustic_maps/emitter_list.glsl: packed emitter texels and the forward
// pass's cost statistics slots.
static const uint kStatForwardSegments = 64u;
static const uint kStatEmitterTexels = 65u;
static const uint kStatDispatchedTexels = 66u;
static const uint kStatGatherLaunches = 67u;

uint packEmitter(uint2 texel, uint layer) { return texel.x | (texel.y << 13) | (layer << 26); }
uint2 emitterTexel(uint packed) { return uint2(packed & 0x1FFFu, (packed >> 13) & 0x1FFFu); }
uint emitterLayer(uint packed) { return packed >> 26; }
#endif
