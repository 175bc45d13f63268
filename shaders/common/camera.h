#ifndef CAUSTICS_COMMON_CAMERA_H
#define CAUSTICS_COMMON_CAMERA_H
// Pinhole camera projection and the light-tracing (splatting) estimator; derivation in
// docs/physics.md ("Camera importance"). Pixel coordinates are continuous, origin at the top-left
// corner of the image, x right, y down; pixel (i, j) covers [i, i+1) x [j, j+1).
#include "common/lang.h"

CAUSTICS_SHARED_BEGIN

struct PinholeCamera {
    float3 eye;
    float3 right;    // unit, image +x
    float3 up;       // unit, image -y
    float3 forward;  // unit, optical axis
    float tanHalfFovY;
    float aspect;    // width / height
    float width;
    float height;
};

CAUSTICS_FN PinholeCamera makePinholeCamera(float3 eye, float3 target, float3 upHint, float verticalFov, float width, float height) {
    PinholeCamera c;
    c.eye = eye;
    c.forward = normalize(target - eye);
    c.right = normalize(cross(c.forward, upHint));
    c.up = cross(c.right, c.forward);
    c.tanHalfFovY = tan(0.5f * verticalFov);
    c.aspect = width / height;
    c.width = width;
    c.height = height;
    return c;
}

// Area of one pixel on the image plane at unit distance from the pinhole.
CAUSTICS_FN float pinholePixelArea(PinholeCamera c) {
    float imageArea = 4.0f * c.tanHalfFovY * c.tanHalfFovY * c.aspect;
    return imageArea / (c.width * c.height);
}

struct CameraProjection {
    float2 pixel;     // continuous pixel coordinates
    float distance;   // |x - eye|
    float cosTheta;   // cosine between the optical axis and the direction eye -> x
    float depth;      // distance along the optical axis
    bool valid;       // in front of the camera and inside the image
};

CAUSTICS_FN CameraProjection projectToCamera(PinholeCamera c, float3 x) {
    CameraProjection p;
    float3 v = x - c.eye;
    p.depth = dot(v, c.forward);
    p.distance = length(v);
    p.cosTheta = p.depth / max(p.distance, 1.0e-30f);
    p.pixel = splat2(-1.0f);
    p.valid = false;
    if (p.depth <= 0.0f) return p;
    float sx = dot(v, c.right) / (p.depth * c.tanHalfFovY * c.aspect);  // [-1, 1] across the image
    float sy = dot(v, c.up) / (p.depth * c.tanHalfFovY);
    p.pixel = float2((0.5f * sx + 0.5f) * c.width, (0.5f - 0.5f * sy) * c.height);
    p.valid = p.pixel.x >= 0.0f && p.pixel.x < c.width && p.pixel.y >= 0.0f && p.pixel.y < c.height;
    return p;
}

// Unit direction from the eye through a continuous pixel position (inverse of projectToCamera).
CAUSTICS_FN float3 cameraRayDirection(PinholeCamera c, float2 pixel) {
    float sx = 2.0f * pixel.x / c.width - 1.0f;
    float sy = 1.0f - 2.0f * pixel.y / c.height;
    return normalize(c.forward + (sx * c.tanHalfFovY * c.aspect) * c.right + (sy * c.tanHalfFovY) * c.up);
}

// Directional importance W_e of a pixel of a pinhole camera, for directions through that pixel:
// 1 / (A_pixel cos^4 theta) (Veach 1997 sec. 10.2; PBRT 3e sec. 16.1.1), which makes the pixel value
// the mean radiance over the pixel's area on the image plane.
CAUSTICS_FN float pinholeImportance(PinholeCamera c, float cosThetaCamera) {
    float c2 = cosThetaCamera * cosThetaCamera;
    return 1.0f / (pinholePixelArea(c) * c2 * c2);
}

// Light-tracing estimator: a photon of flux Phi arriving at a surface point x adds
//   Phi * f_r(x) * pinholeSplatFactor(...)
// to the pixel x projects into, with
//   pinholeSplatFactor = W_e * G(x <-> eye) = cos(theta_surface) / (A_pixel cos^3(theta_camera) d^2),
// theta_surface between the surface normal and x -> eye, theta_camera between the optical axis and
// eye -> x, d = |x - eye|. Units: lm * sr^-1 * m^-2 = cd/m^2 (radiance) when Phi is in lumens.
CAUSTICS_FN float pinholeSplatFactor(PinholeCamera c, float cosThetaCamera, float cosThetaSurface, float distance) {
    float c3 = cosThetaCamera * cosThetaCamera * cosThetaCamera;
    return cosThetaSurface / (pinholePixelArea(c) * c3 * distance * distance);
}

CAUSTICS_SHARED_END

// caustics::CameraConstants (passes/internal/caustics/camera_constants.h) as every pass's shaders see
// it (docs/shaders.md, "Scene API"): one uniform block per pass. std140, std430 and the HLSL
// constant-buffer layout give the same offsets, because every member is a float4x4, float4 or uint4
// (the C++ layout is checked member by member in passes/module/scene_layout_check.cpp).
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

#endif  // CAUSTICS_COMMON_CAMERA_H
