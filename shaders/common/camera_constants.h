#ifndef CAUSTICS_COMMON_CAMERA_CONSTANTS_H
#define CAUSTICS_COMMON_CAMERA_CONSTANTS_H
// caustics::CameraConstants (passes/internal/caustics/camera_constants.h) as every pass's shaders see
// it, in the shared dialect (docs/shaders.md, "Scene API"): one uniform block per pass, e.g. GLSL
//   layout(set = 1, binding = 0) uniform CameraBlock { CameraConstants camera; };
// std140, std430 and the HLSL constant-buffer layout give the same offsets, because every member is a
// float4x4, float4 or uint4 (the C++ layout is checked member by member in scene_layout_check.cpp).
#include "common/camera.h"
#include "common/matrix.h"

CAUSTICS_SHARED_BEGIN
struct CameraConstants {
    float4x4 view;          // world -> view
    float4x4 proj;          // view -> clip (Vulkan clip: y down, z 0..1)
    float4x4 viewProj;
    float4x4 invViewProj;
    float4x4 prevViewProj;
    float4 eye;             // xyz eye, w jitter x (pixels)
    float4 forward;         // xyz optical axis, w tan(fovY / 2)
    float4 right;           // xyz image +x, w aspect
    float4 up;              // xyz image -y, w jitter y (pixels)
    float4 clip;            // x near, y far (0 = infinite), z 1/width, w 1/height
    uint4 frame;            // x width, y height, z frame index, w 1 = reversed Z
};

// The same camera as shaders/common/camera.h's PinholeCamera (projection and splat factors).
CAUSTICS_FN PinholeCamera cameraPinhole(CameraConstants c) {
    PinholeCamera p;
    p.eye = toFloat3(c.eye);
    p.right = toFloat3(c.right);
    p.up = toFloat3(c.up);
    p.forward = toFloat3(c.forward);
    p.tanHalfFovY = c.forward.w;
    p.aspect = c.right.w;
    p.width = float(c.frame.x);
    p.height = float(c.frame.y);
    return p;
}

// The projection centre sits at the image centre plus the host's sub-pixel jitter (eye.w, up.w;
// docs/embedding.md "Camera"): the pinhole model is centred, so pixels shift by the jitter.
CAUSTICS_FN float2 cameraJitter(CameraConstants c) { return float2(c.eye.w, c.up.w); }

// Unit world-space direction from the eye through the continuous pixel position `pixel`.
CAUSTICS_FN float3 cameraPixelDirection(CameraConstants c, float2 pixel) {
    return cameraRayDirection(cameraPinhole(c), pixel - cameraJitter(c));
}

// projectToCamera (shaders/common/camera.h) for the jittered image this frame's G-buffer was drawn with.
CAUSTICS_FN CameraProjection cameraProject(CameraConstants c, float3 x) {
    PinholeCamera cam = cameraPinhole(c);
    CameraProjection p = projectToCamera(cam, x);
    p.pixel += cameraJitter(c);
    p.valid = p.depth > 0.0f && p.pixel.x >= 0.0f && p.pixel.x < cam.width && p.pixel.y >= 0.0f && p.pixel.y < cam.height;
    return p;
}

// World position of a G-buffer pixel from its linear depth (distance along the optical axis).
CAUSTICS_FN float3 cameraWorldPosition(CameraConstants c, float2 pixel, float linearDepth) {
    float3 d = cameraPixelDirection(c, pixel);
    return toFloat3(c.eye) + d * (linearDepth / dot(d, toFloat3(c.forward)));
}
CAUSTICS_SHARED_END

#endif  // CAUSTICS_COMMON_CAMERA_CONSTANTS_H
