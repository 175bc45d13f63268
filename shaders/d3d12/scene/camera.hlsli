#ifndef CAUSTICS_D3D12_CAMERA_HLSLI
#define CAUSTICS_D3D12_CAMERA_HLSLI
// The camera constants and their functions are the shared dialect's common/camera.h. proj
// is Vulkan's (clip y down): raster vertex shaders negate clip y (vulkanToD3DClip).
#include "common/camera.h"

// Vulkan clip space has y down, D3D's y up: negating y makes the rasterized image (and the winding
// the rasterizer sees) identical to the Vulkan backend's.
float4 vulkanToD3DClip(float4 clip) { return float4(clip.x, -clip.y, clip.z, clip.w); }
#endif
