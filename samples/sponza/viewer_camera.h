#pragma once
// The viewer's camera: fly (WASD + mouse look, Q/E down/up, a speed) or orbit (drag around a target,
// wheel to dolly). Both keep yaw/pitch so switching modes never jumps; reset returns to the start view.
#include "caustics/scene/scene.h"

namespace caustics::sample {

enum class CameraMode { Orbit, Fly };

class ViewerCamera {
public:
    // `start` is the view `reset()` returns to; `sceneRadius` scales speeds and the dolly range.
    ViewerCamera(const scene::Camera& start, float sceneRadius);

    void reset() { *this = ViewerCamera(start_, sceneRadius_); }
    void setView(const scene::Camera& view);   // e.g. one of the glTF cameras; keeps the mode
    void setMode(CameraMode mode);
    CameraMode mode() const { return mode_; }

    // Mouse motion in pixels while the look/orbit button is held.
    void drag(float dx, float dy);
    // Orbit: dolly by wheel steps; fly: change the speed.
    void scroll(float steps);
    // Fly: move along (right, up, forward) by `seconds` at the current speed; orbit: forward dollies.
    void move(const glm::vec3& axes, float seconds);

    float speed = 1.0f;          // fly speed, metres per second
    scene::Camera camera() const;   // eye/target/up/fov; near/far are the caller's (fitClipPlanes)

private:
    glm::vec3 forward() const;

    scene::Camera start_;
    float sceneRadius_ = 1.0f;
    CameraMode mode_ = CameraMode::Orbit;
    glm::vec3 target_{0.0f};
    glm::vec3 eye_{0.0f};
    float yaw_ = 0.0f, pitch_ = 0.0f;   // direction from the eye to the target
    float distance_ = 1.0f;
    glm::vec3 up_{0.0f, 1.0f, 0.0f};
    float fov_ = 0.785398f;
};

}  // namespace caustics::sample
