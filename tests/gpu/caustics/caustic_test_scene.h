#pragma once
// The small scene the caustic-pass GPU tests share: a glass sphere over a diffuse plane under a
// directional light, seen obliquely so that the focal spot appears both directly (first type) and
// through the sphere (second type).
#include "caustics/caustics_settings.h"
#include "caustics/scene/builtin_scenes.h"

namespace caustics::test {

inline scene::Scene smallGlassSphereScene() {
    scene::AnalyticSceneDesc d;
    d.radius = 0.5f;
    d.height = 0.8f;
    d.tessellation = 32;
    d.lightDirection = glm::normalize(glm::vec3(0.3f, -1.0f, 0.0f));
    return scene::makeGlassSphereScene(d);
}

inline scene::Camera obliqueCamera() {
    scene::Camera c;
    c.eye = {0.0f, 1.6f, 2.2f};
    c.target = {-0.1f, 0.2f, 0.0f};
    c.verticalFovRadians = glm::radians(50.0f);
    return c;
}

inline CausticsSettings smallSettings() {
    CausticsSettings s;
    s.mapResolution = 64;
    s.raysPerTexel = 1.0f;
    s.filter = false;
    s.maxStoredHits = 1u << 16;
    s.sphereRadiusPolicy = SphereRadiusPolicy::FixedWorld;
    s.sphereWorldRadius = 0.05f;
    return s;
}

// The filter tests' glass ball (caustic_filter_test.cpp): its focal spot lies on the floor beside it.
inline scene::Scene filterBallScene() {
    scene::AnalyticSceneDesc d;
    d.radius = 0.5f;
    d.tessellation = 96;
    d.lightDirection = glm::normalize(glm::vec3(0.6f, -1.0f, 0.0f));
    d.height = 0.75f * -d.lightDirection.y;
    return scene::makeGlassSphereScene(d);
}

inline scene::Camera towardsTheFilterBallSpot() {
    scene::Camera c;
    c.eye = {1.6f, 1.0f, 1.2f};
    c.target = {0.35f, 0.0f, 0.0f};
    c.verticalFovRadians = glm::radians(30.0f);
    return c;
}

}  // namespace caustics::test
