#ifndef CAUSTICS_D3D12_CAMERA_HLSLI
#define CAUSTICS_D3D12_CAMERA_HLSLI
// Mirror of shaders/vulkan/scene/camera.glsl (caustics::CameraConstants). Matrices are glm's
// column-major; HLSL constant buffers default to column_major packing, so mul(M, v) is GLSL's M * v.
// proj is Vulkan's (clip y down): raster vertex shaders negate clip y (vulkanToD3DClip).
#include "common/camera.h"

struct CameraConstants {
    float4x4 view;
    float4x4 proj;
    float4x4 viewProj;
    float4x4 invViewProj;
    float4x4 prevViewProj;
    float4 eye;       // w jitter x (pixels)
    float4 forward;   // w tan(fovY / 2)
    float4 right;     // w aspect
    float4 up;        // w jitter y (pixels)
    float4 clip;      // x near, y far (0 = infinite), z 1/width, w 1/height
    uint4 frame;      // x width, y height, z frame index, w 1 = reversed Z
};

// Vulkan clip space has y down, D3D's y up: negating y makes the rasterized image (and the winding
// the rasterizer sees) identical to the Vulkan backend's.
float4 vulkanToD3DClip(float4 clip) { return float4(clip.x, -clip.y, clip.z, clip.w); }

PinholeCamera cameraPinhole(CameraConstants c) {
    PinholeCamera p;
    p.eye = c.eye.xyz;
    p.right = c.right.xyz;
    p.up = c.up.xyz;
    p.forward = c.forward.xyz;
    p.tanHalfFovY = c.forward.w;
    p.aspect = c.right.w;
    p.width = float(c.frame.x);
    p.height = float(c.frame.y);
    return p;
}

// The host's sub-pixel jitter (camera.glsl explains it).
float2 cameraJitter(CameraConstants c) { return float2(c.eye.w, c.up.w); }

float3 cameraPixelDirection(CameraConstants c, float2 pixel) {
    return cameraRayDirection(cameraPinhole(c), pixel - cameraJitter(c));
}

CameraProjection cameraProject(CameraConstants c, float3 x) {
    PinholeCamera cam = cameraPinhole(c);
    CameraProjection p = projectToCamera(cam, x);
    p.pixel += cameraJitter(c);
    p.valid = p.depth > 0.0f && p.pixel.x >= 0.0f && p.pixel.x < cam.width && p.pixel.y >= 0.0f && p.pixel.y < cam.height;
    return p;
}

float3 cameraWorldPosition(CameraConstants c, float2 pixel, float linearDepth) {
    float3 d = cameraPixelDirection(c, pixel);
    return c.eye.xyz + d * (linearDepth / dot(d, c.forward.xyz));
}
#endif
