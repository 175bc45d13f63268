#ifndef CAUSTICS_D3D12_SPHERE_LIST_HLSLI
#define CAUSTICS_D3D12_SPHERE_LIST_HLSLI
// Mirror of shaders/vulkan/backward_trace/sphere_list.glsl: statistics slots of the second type's cost.
static const uint kStatSpecularPixels = 69u;
static const uint kStatBackwardLaunches = 70u;
static const uint kStatSpheresDropped = 71u;
static const uint kStatSphereCapacity = 72u;
#endif
