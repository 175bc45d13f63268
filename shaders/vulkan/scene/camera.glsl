#ifndef CAUSTICS_SCENE_CAMERA_GLSL
#define CAUSTICS_SCENE_CAMERA_GLSL
// GLSL mirror of caustics::CameraConstants (passes/include/caustics/camera_constants.h), member for
// member; std140 and std430 give the same offsets because every member is a vec4/mat4/uvec4.
// Declare the block yourself where you want it, e.g.
//   layout(set = 1, binding = 0) uniform CameraBlock { CameraConstants camera; };
#include "common/camera.h"

struct CameraConstants {
    mat4 view;          // world -> view
    mat4 proj;          // view -> clip (Vulkan clip: y down, z 0..1)
    mat4 viewProj;
    mat4 invViewProj;
    mat4 prevViewProj;
    vec4 eye;           // xyz eye, w jitter x (pixels)
    vec4 forward;       // xyz optical axis, w tan(fovY / 2)
    vec4 right;         // xyz image +x, w aspect
    vec4 up;            // xyz image -y, w jitter y (pixels)
    vec4 clip;          // x near, y far (0 = infinite), z 1/width, w 1/height
    uvec4 frame;        // x width, y height, z frame index, w 1 = reversed Z
};

// The same camera as shaders/common/camera.h's PinholeCamera (projection and splat factors).
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

// The projection centre sits at the image centre plus the host's sub-pixel jitter (eye.w, up.w;
// docs/embedding.md "Camera"): the pinhole model is centred, so pixels shift by the jitter.
vec2 cameraJitter(CameraConstants c) { return vec2(c.eye.w, c.up.w); }

// Unit world-space direction from the eye through the continuous pixel position `pixel`.
vec3 cameraPixelDirection(CameraConstants c, vec2 pixel) {
    return cameraRayDirection(cameraPinhole(c), pixel - cameraJitter(c));
}

// projectToCamera (shaders/common/camera.h) for the jittered image this frame's G-buffer was drawn with.
CameraProjection cameraProject(CameraConstants c, vec3 x) {
    PinholeCamera cam = cameraPinhole(c);
    CameraProjection p = projectToCamera(cam, x);
    p.pixel += cameraJitter(c);
    p.valid = p.depth > 0.0 && p.pixel.x >= 0.0 && p.pixel.x < cam.width && p.pixel.y >= 0.0 && p.pixel.y < cam.height;
    return p;
}

// World position of a G-buffer pixel from its linear depth (distance along the optical axis).
vec3 cameraWorldPosition(CameraConstants c, vec2 pixel, float linearDepth) {
    vec3 d = cameraPixelDirection(c, pixel);
    return c.eye.xyz + d * (linearDepth / dot(d, c.forward.xyz));
}

#endif
