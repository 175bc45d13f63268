#include "viewer_camera.h"

#include <algorithm>
#include <cmath>

#include "camera_setup.h"

namespace caustics::sample {
namespace {
constexpr float kRadiansPerPixel = 0.005f;
constexpr float kMaxPitch = 1.55f;   // just short of straight up/down: the yaw stays meaningful
}  // namespace

ViewerCamera::ViewerCamera(const scene::Camera& start, float sceneRadius)
    : start_(start), sceneRadius_(std::max(sceneRadius, 1e-3f)) {
    speed = 0.5f * sceneRadius_;   // cross the scene in about four seconds
    setView(start);
}

void ViewerCamera::setView(const scene::Camera& view) {
    eye_ = view.eye;
    target_ = view.target;
    up_ = view.up;
    fov_ = view.verticalFovRadians;
    glm::vec3 d = target_ - eye_;
    distance_ = std::max(glm::length(d), 1e-4f);
    d /= distance_;
    pitch_ = std::asin(std::clamp(d.y, -1.0f, 1.0f));
    yaw_ = std::atan2(d.x, -d.z);
}

void ViewerCamera::setMode(CameraMode mode) { mode_ = mode; }

glm::vec3 ViewerCamera::forward() const {
    return {std::cos(pitch_) * std::sin(yaw_), std::sin(pitch_), -std::cos(pitch_) * std::cos(yaw_)};
}

void ViewerCamera::drag(float dx, float dy) {
    yaw_ += dx * kRadiansPerPixel;
    pitch_ = std::clamp(pitch_ - dy * kRadiansPerPixel, -kMaxPitch, kMaxPitch);
    up_ = glm::vec3(0.0f, 1.0f, 0.0f);
    // Orbit keeps the target and swings the eye; fly keeps the eye and turns the view.
    if (mode_ == CameraMode::Orbit) eye_ = target_ - distance_ * forward();
    else target_ = eye_ + distance_ * forward();
}

void ViewerCamera::scroll(float steps) {
    if (mode_ == CameraMode::Fly) {
        speed = std::clamp(speed * std::pow(1.25f, steps), 1e-3f * sceneRadius_, 100.0f * sceneRadius_);
        return;
    }
    distance_ = std::clamp(distance_ * std::pow(0.9f, steps), 1e-3f * sceneRadius_, 1e3f * sceneRadius_);
    eye_ = target_ - distance_ * forward();
}

void ViewerCamera::move(const glm::vec3& axes, float seconds) {
    glm::vec3 f = forward();
    if (mode_ == CameraMode::Orbit) {
        if (axes.z != 0.0f) scroll(axes.z * seconds * 10.0f);
        return;
    }
    glm::vec3 right = glm::normalize(glm::cross(f, robustUp(f, glm::vec3(0.0f, 1.0f, 0.0f))));
    glm::vec3 step = (axes.x * right + axes.y * glm::vec3(0.0f, 1.0f, 0.0f) + axes.z * f) * speed * seconds;
    eye_ += step;
    target_ = eye_ + distance_ * f;
}

scene::Camera ViewerCamera::camera() const {
    scene::Camera c = start_;
    c.eye = eye_;
    c.target = target_;
    c.verticalFovRadians = fov_;
    c.up = robustUp(target_ - eye_, up_);
    return c;
}

}  // namespace caustics::sample
