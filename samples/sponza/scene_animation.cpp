#include "scene_animation.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "caustics/scene/mesh_utils.h"

namespace caustics::sample {
namespace {

constexpr float kTwoPi = 6.2831853f;
// The path's half-width as a fraction of the glass group's larger horizontal extent: far enough that
// the caustics visibly travel, near enough that the group stays on the surface it stands on.
constexpr float kPathRadiusFraction = 0.35f;
constexpr float kMaxYawRadians = 0.5235988f;   // 30 degrees each way

glm::mat4 yawAbout(const glm::vec3& centre, float radians) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), centre);
    m = glm::rotate(m, radians, glm::vec3(0.0f, 1.0f, 0.0f));
    return glm::translate(m, -centre);
}

}  // namespace

SceneAnimation SceneAnimation::capture(const scene::Scene& scene) {
    SceneAnimation a;
    for (size_t i = 0; i < scene.instances.size(); ++i)
        if (scene::isSpecularInstance(scene, scene.instances[i])) a.glass_.push_back({i, scene.instances[i].transform});
    scene::Aabb glass = scene::specularBounds(scene);
    scene::Aabb all = scene::sceneBounds(scene);
    a.centre_ = !glass.empty() ? glass.center() : all.empty() ? glm::vec3(0.0f) : all.center();
    glm::vec3 extent = glass.extent();
    a.pathRadius_ = kPathRadiusFraction * std::max(extent.x, extent.z);
    return a;
}

void SceneAnimation::advance(float seconds) {
    if (toggles.paused) return;
    float step = seconds * toggles.speed;
    if (toggles.objects) objectClock_ += step;
    if (!toggles.orbitingLights.empty()) lightClock_ += step;
}

// A figure-eight x = r sin(phi), z = (r/2) sin(2 phi) that starts at the rest pose (phi = 0) and
// passes through a pure translation by (r, 0, 0) at phi = pi/2 (the yaw, r/2 sin(2 phi)'s twin, is 0
// there too): the tests' expected caustic shift comes from that point.
GroupPose SceneAnimation::groupPose(float seconds) const {
    float phi = kTwoPi * seconds / kAnimationPeriodSeconds;
    GroupPose p;
    p.offset = {pathRadius_ * std::sin(phi), 0.0f, 0.5f * pathRadius_ * std::sin(2.0f * phi)};
    p.yawRadians = kMaxYawRadians * std::sin(2.0f * phi);
    return p;
}

scene::Light SceneAnimation::orbitLight(const scene::Light& light, float seconds) const {
    float angle = kTwoPi * seconds / kAnimationPeriodSeconds;
    glm::mat4 turn = yawAbout(centre_, angle);
    scene::Light l = light;
    l.position = glm::vec3(turn * glm::vec4(light.position, 1.0f));
    l.direction = glm::normalize(glm::vec3(turn * glm::vec4(light.direction, 0.0f)));
    return l;
}

void SceneAnimation::apply(scene::Scene& scene, const std::vector<scene::Light>& restLights) const {
    glm::mat4 motion(1.0f);
    if (toggles.objects) {
        GroupPose pose = groupPose(objectClock_);
        motion = glm::translate(glm::mat4(1.0f), pose.offset) * yawAbout(centre_, pose.yawRadians);
    }
    for (const Glass& g : glass_)
        if (g.instance < scene.instances.size()) scene.instances[g.instance].transform = motion * g.rest;
    scene.lights = restLights;
    for (uint32_t i : toggles.orbitingLights)
        if (i < scene.lights.size()) scene.lights[i] = orbitLight(restLights[i], lightClock_);
}

}  // namespace caustics::sample
