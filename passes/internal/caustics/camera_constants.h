#pragma once
// Camera constants shared by every pass (one uniform/storage block; the shaders' declaration is
// shaders/common/camera.h, checked member for member in passes/module/scene_layout_check.cpp). Only
// mat4/vec4/uvec4 members, so the std140 and std430 layouts are identical and equal to the C++ layout
// (static_asserts below).
//
// Conventions: right-handed world, camera looks along `forward`; clip space is Vulkan's (x right,
// y DOWN, z 0..1), i.e. proj already carries the y flip, so NDC (-1,-1) is the top-left image corner
// and pixel (i, j) covers [i, i+1) x [j, j+1) like shaders/common/camera.h.
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include "caustics/camera_view.h"
#include "caustics/rhi/result.h"
#include "caustics/scene/scene.h"

namespace caustics {

struct CameraConstants {
    glm::mat4 view{1.0f};          //   0 world -> view (view looks down -Z)
    glm::mat4 proj{1.0f};          //  64 view -> clip
    glm::mat4 viewProj{1.0f};      // 128
    glm::mat4 invViewProj{1.0f};   // 192 clip -> world
    glm::mat4 prevViewProj{1.0f};  // 256 last frame's viewProj (temporal reprojection)
    glm::vec4 eye{0.0f};           // 320 xyz eye position, w jitter x (pixels, ProjectionInfo)
    glm::vec4 forward{0.0f};       // 336 xyz unit optical axis, w tan(verticalFov / 2)
    glm::vec4 right{0.0f};         // 352 xyz unit image +x, w aspect (width / height)
    glm::vec4 up{0.0f};            // 368 xyz unit image -y (world up on screen), w jitter y (pixels)
    glm::vec4 clip{0.0f};          // 384 x near, y far (0 = infinite), z 1/width, w 1/height
    glm::uvec4 frame{0u};          // 400 x width, y height, z frame index, w 1 = reversed Z
};
static_assert(sizeof(CameraConstants) == 416);
static_assert(offsetof(CameraConstants, proj) == 64);
static_assert(offsetof(CameraConstants, invViewProj) == 192);
static_assert(offsetof(CameraConstants, prevViewProj) == 256);
static_assert(offsetof(CameraConstants, eye) == 320);
static_assert(offsetof(CameraConstants, forward) == 336);
static_assert(offsetof(CameraConstants, clip) == 384);
static_assert(offsetof(CameraConstants, frame) == 400);
static_assert(sizeof(CameraConstants) % 16 == 0, "std140 arrays and uniform ranges need 16-byte multiples");

// Builds the constants for an image of width x height from the host's matrices (camera_view.h): the
// eye, axes, field of view, jitter and depth convention are read back from view and proj.
// prevViewProj: last frame's viewProj (nullptr: the current one, i.e. no motion). Fails, naming the
// entry, for a projection analyzeProjection() refuses or a view matrix that is not a rigid transform.
Result<CameraConstants> makeCameraConstants(const glm::mat4& view, const glm::mat4& proj, uint32_t width,
                                            uint32_t height, uint32_t frameIndex,
                                            const glm::mat4* prevViewProj = nullptr);

// The same for an eye/target/fov camera with a standard projection (samples and tests). A degenerate
// camera (eye == target, fov or near/far out of range) is refused naming the field.
Result<CameraConstants> makeCameraConstants(const scene::Camera& camera, uint32_t width, uint32_t height,
                                            uint32_t frameIndex, const glm::mat4* prevViewProj = nullptr);

}  // namespace caustics
