#pragma once
// The viewer's and the headless sample's animation (docs/viewer.md "Animation"): the glass objects
// (instances whose material is specular, scene::Material::isSpecular) travel together along a closed
// figure-eight path on their supporting surface and yaw back and forth about their common centre; the
// selected lights orbit the vertical axis through that centre, turning with it so that a spot keeps its
// aim. Everything goes through the module's live scene (docs/embedding.md "A live scene"): the scene is
// rewritten before each frame, nothing is rebuilt. Poses are a pure function of the animation clocks,
// so a script or a headless run that advances them by a fixed step per frame is deterministic.
#include <cstdint>
#include <set>
#include <vector>

#include <glm/glm.hpp>

#include "caustics/scene/scene.h"

namespace caustics::sample {

// One full figure-eight of the objects and one full orbit of a light take this long at speed 1.
inline constexpr float kAnimationPeriodSeconds = 8.0f;
// The clock step of one frame where time must not depend on the machine (--script, headless).
inline constexpr float kFixedFrameSeconds = 1.0f / 30.0f;
inline constexpr float kMaxAnimationSpeed = 100.0f;

struct AnimationToggles {
    bool objects = false;                  // glass objects follow their path
    std::set<uint32_t> orbitingLights;     // indices into Scene::lights
    float speed = 1.0f;                    // clock rate, (0, kMaxAnimationSpeed]
    bool paused = false;                   // both clocks stop; poses stay where they are
};

// The rigid motion of the glass group at object-clock time `seconds` (speed already applied).
struct GroupPose {
    glm::vec3 offset{0.0f};   // translation of the group, metres
    float yawRadians = 0.0f;  // rotation about the vertical axis through the group's centre
};

class SceneAnimation {
public:
    // Records the rest pose: which instances are glass, their transforms, the centre they turn about
    // (the glass objects' bounds centre; the scene's when there is no glass) and the path's size.
    static SceneAnimation capture(const scene::Scene& scene);

    // Advances the clocks by `seconds` of wall or fixed time times the speed; a clock runs only while
    // its animation is on and not paused, so switching one on starts it from where it stopped.
    void advance(float seconds);

    // Writes the poses into `scene`: glass instances (rest pose when objects are off) and lights
    // (`restLights` as edited by the user, orbiting ones turned about the centre).
    void apply(scene::Scene& scene, const std::vector<scene::Light>& restLights) const;

    GroupPose groupPose(float seconds) const;
    // `light` turned about the centre's vertical axis by the orbit angle of `seconds`.
    scene::Light orbitLight(const scene::Light& light, float seconds) const;

    AnimationToggles toggles;
    float objectSeconds() const { return objectClock_; }
    float lightSeconds() const { return lightClock_; }
    size_t glassCount() const { return glass_.size(); }
    glm::vec3 centre() const { return centre_; }
    float pathRadius() const { return pathRadius_; }

private:
    struct Glass {
        size_t instance;
        glm::mat4 rest;
    };
    std::vector<Glass> glass_;
    glm::vec3 centre_{0.0f};
    float pathRadius_ = 0.0f;
    float objectClock_ = 0.0f, lightClock_ = 0.0f;
};

}  // namespace caustics::sample
