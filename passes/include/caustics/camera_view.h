#pragma once
// The host's camera as the module takes it: view and projection matrices (docs/embedding.md,
// "Camera"). The projection is any perspective projection in Vulkan clip space (x right, y DOWN,
// z 0..1, right-handed view looking down -Z) with
//   - sub-pixel jitter (TAA): the offsets in the third column, proj[2][0] and proj[2][1];
//   - standard (near 0, far 1) or reversed (near 1, far 0) depth;
//   - a finite or an infinite far plane.
// cameraViewMatrices() turns the samples' eye/target/fov camera into such matrices.
#include <cstdint>
#include <optional>

#include <glm/glm.hpp>

#include "caustics/rhi/result.h"
#include "caustics/scene/scene.h"

namespace caustics {

struct CameraView {
    glm::mat4 view{1.0f};   // world -> view
    glm::mat4 proj{1.0f};   // view -> Vulkan clip (y flip included), possibly jittered
    // Last frame's view-projection for the filter's reprojection. Unset: the module uses this view's
    // own record of the previous executed frame (CausticsViewState).
    std::optional<glm::mat4> prevViewProj;
    // Sub-pixel jitter (TAA) given apart from the matrices, as most engines keep it: `proj` and
    // `prevViewProj` are then UNjittered, the module jitters proj by this and prevViewProj by the
    // jitter of the view's last executed frame. Unset: proj carries the jitter (proj[2][0], [2][1]) and
    // prevViewProj must carry last frame's. Pixels, x right, y down (ProjectionOptions::jitterPixels).
    std::optional<glm::vec2> jitterPixels;
};

// `clipMatrix` (a projection or a view-projection) with its image shifted by `jitterPixels`: the
// clip-space translation x += 2 jx / width * w, y += 2 jy / height * w (the convention analyzeProjection
// reads back from proj[2][0], proj[2][1]).
glm::mat4 jitterClipMatrix(const glm::mat4& clipMatrix, glm::vec2 jitterPixels, uint32_t width, uint32_t height);

// What the passes need to know about a projection, read back from its matrix.
struct ProjectionInfo {
    float tanHalfFovY = 0.0f;
    float aspect = 1.0f;          // tan(half fov x) / tan(half fov y)
    float nearPlane = 0.0f;
    float farPlane = 0.0f;        // +infinity for an infinite far plane
    bool reversedZ = false;       // depth 1 at the near plane, 0 at the far plane
    glm::vec2 jitterPixels{0.0f}; // image offset of the projection centre, in pixels (x right, y down)
};

// Refuses what is not a perspective projection of the convention above, naming the matrix entry.
Result<ProjectionInfo> analyzeProjection(const glm::mat4& proj, uint32_t width, uint32_t height);

struct ProjectionOptions {
    bool reversedZ = false;
    bool infiniteFar = false;          // ignores Camera::farPlane
    glm::vec2 jitterPixels{0.0f};      // sub-pixel offset (e.g. a Halton sequence), x right, y down
};

// The helper for hosts and samples that think in eye/target/fov (scene::Camera).
CameraView cameraViewMatrices(const scene::Camera& camera, uint32_t width, uint32_t height,
                              const ProjectionOptions& options = {});

}  // namespace caustics
