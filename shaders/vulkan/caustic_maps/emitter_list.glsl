#ifndef CAUSTICS_EMITTER_LIST_GLSL
#define CAUSTICS_EMITTER_LIST_GLSL
// The emitter list of caustics.emitters (docs/caustics.md, "Cost"): one uint per map texel that emits,
// x | y << 13 | layer << 26 (map side <= 8192, <= 64 layers; passes/caustic_maps/caustic_emitters_pass.cpp
// checks both), and the statistics slots of the forward pass's cost (mirror of caustic_passes.h).
const uint kStatForwardSegments = 64u;   // kStatRaysPerLight + kMaxCausticLights
const uint kStatEmitterTexels = 65u;
const uint kStatDispatchedTexels = 66u;
const uint kStatGatherLaunches = 67u;

uint packEmitter(uvec2 texel, uint layer) { return texel.x | (texel.y << 13) | (layer << 26); }
uvec2 emitterTexel(uint packed) { return uvec2(packed & 0x1FFFu, (packed >> 13) & 0x1FFFu); }
uint emitterLayer(uint packed) { return packed >> 26; }
#endif
