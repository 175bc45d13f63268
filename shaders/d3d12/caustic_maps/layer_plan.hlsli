#ifndef CAUSTICS_D3D12_LAYER_PLAN_HLSLI
#define CAUSTICS_D3D12_LAYER_PLAN_HLSLI
// std430 caustics::CausticLayerPlanGpu (32 bytes) in a byte-address buffer (mirror of
// shaders/vulkan/caustic_maps/layer_plan.glsl): one layer's share of the frame's photons.
static const uint kLayerPlanBytes = 32u;
static const uint kLayerPlanEmitters = 0u;
static const uint kLayerPlanRaysPerTexel = 4u;
static const uint kLayerPlanSamplesPerTexel = 8u;
static const uint kLayerPlanLaunchOffset = 12u;
static const uint kLayerPlanLaunches = 16u;
static const uint kLayerPlanEmitted = 20u;
uint layerPlanAddress(uint layer, uint field) { return kLayerPlanBytes * layer + field; }
#endif
