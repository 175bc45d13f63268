#pragma once
// The embedding tests' scene: the analytic glass sphere (IOR 1.5) above a diffuse plane, lit by one
// spot light from above instead of the sun, so that a turning light and a moving sphere both move the
// focal spot. pose(t) places both for path parameter t in [0, 1].
#include <cmath>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "caustics/scene/builtin_scenes.h"
#include "caustics/scene/scene.h"

namespace caustics::test {

inline constexpr float kSphereRadius = 0.3f;
inline constexpr float kSphereHeight = 0.6f;

inline scene::Scene spotSphereScene() {
    scene::AnalyticSceneDesc d;
    d.radius = kSphereRadius;
    d.height = kSphereHeight;
    d.tessellation = 32;
    d.planeHalfSize = 2.0f;
    scene::Scene s = scene::makeGlassSphereScene(d);
    scene::Light spot;
    spot.name = "turning spot";
    spot.type = scene::LightType::Spot;
    spot.position = {0.0f, 3.0f, 0.0f};
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.intensity = 40.0f;   // candela
    spot.innerConeAngle = 0.0f;
    spot.outerConeAngle = 0.35f;
    s.lights = {spot};
    return s;
}

// Index of the glass sphere's instance (the specular one) in spotSphereScene().
inline uint32_t sphereInstance(const scene::Scene& s) {
    for (uint32_t i = 0; i < s.instances.size(); ++i)
        if (s.materials[s.meshes[s.instances[i].mesh].material].isSpecular()) return i;
    return 0;
}

// Moves the sphere along x from -0.35 to +0.35 m and turns the spot so that it leads the sphere.
inline void poseSpotSphere(scene::Scene& s, float t, const glm::mat4& sphereRest) {
    const float x = -0.35f + 0.7f * t;
    s.instances[sphereInstance(s)].transform = glm::translate(glm::mat4(1.0f), glm::vec3(x, 0.0f, 0.0f)) * sphereRest;
    const glm::vec3 aim(x * 1.2f, 0.0f, 0.1f * t);
    s.lights[0].direction = glm::normalize(aim - s.lights[0].position);
}

inline scene::Camera spotSphereCamera() {
    scene::Camera c;
    c.eye = {0.0f, 2.4f, 1.6f};
    c.target = {0.0f, 0.0f, 0.0f};
    c.verticalFovRadians = 0.75f;
    c.nearPlane = 0.05f;
    c.farPlane = 20.0f;
    return c;
}

}  // namespace caustics::test
