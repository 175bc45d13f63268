#pragma once
// The camera the sample renders: the scene's first camera (or a view framing the scene's bounds),
// overridden by --camera; then made safe to render: an up vector that is never parallel to the view
// direction, and near/far planes that contain the scene however far away the camera is.
#include "cli_options.h"
#include "caustics/scene/scene.h"

namespace caustics::sample {

struct SceneBounds {
    glm::vec3 min{0.0f}, max{0.0f};
    bool empty = true;
    glm::vec3 centre() const { return 0.5f * (min + max); }
    float radius() const { return 0.5f * glm::length(max - min); }
};

// World-space box of every instance (mesh boxes through the instance transforms).
SceneBounds computeSceneBounds(const scene::Scene& scene);

// A camera looking at the bounds' centre from the front and a little above, the whole box in view.
scene::Camera framingCamera(const SceneBounds& bounds, float verticalFovRadians);

// +Y unless the view direction is (nearly) parallel to it; then -Z when looking down, +Z looking up.
glm::vec3 robustUp(const glm::vec3& forward, const glm::vec3& preferredUp);

// Near/far from the distance to the bounds: far reaches past the farthest corner, near is a fixed
// fraction of far (depth precision; see docs/viewer.md) or the camera's own near if that is larger.
void fitClipPlanes(scene::Camera& camera, const SceneBounds& bounds);

scene::Camera cameraFromOptions(const scene::Scene& scene, const CliOptions& options);

}  // namespace caustics::sample
