#pragma once
// The second-type scenes of issue 18, each built twice from one description: as a module scene (meshes,
// glTF materials, a KHR light) and as the independent reference's analytic scene
// (tests/reference/second_type: exact solids, its own optics). docs/physics.md, "Independent
// second-type reference".
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "analytic_scene.h"
#include "caustics/scene/mesh_builder.h"
#include "caustics/scene/mesh_utils.h"
#include "caustics/scene/scene.h"
#include "second_type_scenes.h"

namespace caustics::test {

namespace ref = optics_reference;

struct IndependentCase {
    std::string name;
    scene::Scene module;
    ref::Scene reference;
    scene::Camera camera;
    double receiverX = 0.0, receiverZ = 0.0, receiverHalfSize = 2.0;   // floor square of the histogram
    bool axial = false;             // symmetric about the vertical axis through the receiver centre: radial histogram
    double regionFraction = 0.0;    // compare pixels closer than this x half the image size to the centre (0: all)

    ref::Pinhole pinhole() const {
        ref::Pinhole p;
        p.eye = glm::dvec3(camera.eye);
        p.target = glm::dvec3(camera.target);
        p.up = glm::dvec3(camera.up);
        p.verticalFov = camera.verticalFovRadians;
        return p;
    }
};

// A Lambertian floor (albedo 0.8, no specular layer: radiance albedo E / pi, as the reference's).
inline IndependentCase emptyCase(std::string name) {
    IndependentCase c;
    c.name = std::move(name);
    c.module.name = c.name;
    scene::Material floor;
    floor.name = "floor";
    floor.baseColor = glm::vec3(0.8f);
    floor.roughness = 1.0f;
    floor.specular = 0.0f;
    addSceneObject(c.module, scene::makePlane(4.0f, 4.0f, 8), floor, glm::mat4(1.0f));
    c.reference.floorAlbedo = 0.8;
    return c;
}

inline void addBall(IndependentCase& c, glm::vec3 centre, float radius, float ior) {
    scene::Mesh m = scene::makeSphere(radius, 256, 128);
    scene::sortTrianglesMorton(m);
    addSceneObject(c.module, std::move(m), glassMaterial(ior, 2.0f * radius), glm::translate(glm::mat4(1.0f), centre));
    ref::Object o;
    o.solid = ref::sphereSolid(glm::dvec3(centre), radius);
    o.optic.ior = ior;
    c.reference.objects.push_back(o);
}

// A glass box (half extents in its own frame, `frame`'s columns its axes in world space).
inline void addGlassBox(IndependentCase& c, glm::vec3 centre, glm::vec3 halfExtent, const glm::mat3& frame, float ior) {
    glm::mat4 m(frame);
    m[3] = glm::vec4(centre, 1.0f);
    float thickness = 2.0f * std::min(halfExtent.x, std::min(halfExtent.y, halfExtent.z));
    addSceneObject(c.module, scene::makeBox(halfExtent), glassMaterial(ior, thickness), m);
    ref::Object o;
    o.solid = ref::boxSolid(glm::dvec3(centre), glm::dvec3(halfExtent), glm::dmat3(frame));
    o.optic.ior = ior;
    c.reference.objects.push_back(o);
}

// A 1 cm pane perpendicular to the view axis, `distance` in front of the eye (fills the view).
inline void addPaneInFrontOfCamera(IndependentCase& c, float distance, float halfSize) {
    glm::vec3 axis = glm::normalize(c.camera.target - c.camera.eye);
    glm::vec3 x = glm::normalize(glm::cross(axis, glm::vec3(0.0f, 1.0f, 0.0f)));
    glm::mat3 frame(x, axis, glm::cross(x, axis));   // local y (the 1 cm side) along the view axis
    addGlassBox(c, c.camera.eye + distance * axis, {halfSize, 0.005f, halfSize}, frame, 1.5f);
}

// Thick-walled tube on the floor (base at yBase): glass (ior > 0) or polished metal (ior 0, F0 0.95).
inline void addTube(IndependentCase& c, glm::vec3 base, float outer, float inner, float height, float bottom, float ior) {
    scene::Mesh m = scene::makeTube(outer, inner, height, 256, bottom);
    scene::Material mat = glassMaterial(ior, outer - inner);
    ref::Object o;
    o.solid = ref::tubeSolid(base.x, base.z, base.y, outer, inner, height, bottom);
    if (ior <= 0.0f) {
        mat = scene::Material{};
        mat.name = "polished metal";
        mat.baseColor = glm::vec3(0.95f);
        mat.metallic = 1.0f;
        mat.roughness = 0.0f;
        o.optic.kind = ref::Optic::Kind::Conductor;
        o.optic.f0 = glm::dvec3(0.95);
    } else {
        o.optic.ior = ior;
    }
    addSceneObject(c.module, std::move(m), mat, glm::translate(glm::mat4(1.0f), base));
    c.reference.objects.push_back(o);
}

inline void addWaterColumn(IndependentCase& c, glm::vec3 base, float radius, float height) {
    addSceneObject(c.module, scene::makeCylinder(radius, height, 256, 1, true), glassMaterial(1.33f, 2.0f * radius),
                   glm::translate(glm::mat4(1.0f), base));
    ref::Object o;
    o.solid = ref::cylinderSolid(base.x, base.z, base.y, radius, height);
    o.optic.ior = 1.33;
    c.reference.objects.push_back(o);
}

inline void setSpot(IndependentCase& c, glm::vec3 position, glm::vec3 target, float candela, float outerCone) {
    scene::Light l;
    l.name = "spot";
    l.type = scene::LightType::Spot;
    l.position = position;
    l.direction = glm::normalize(target - position);
    l.intensity = candela;
    l.innerConeAngle = 0.0f;
    l.outerConeAngle = outerCone;
    c.module.lights = {l};
    c.reference.light.directional = false;
    c.reference.light.position = glm::dvec3(position);
    c.reference.light.direction = glm::dvec3(l.direction);
    c.reference.light.intensity = candela;
    c.reference.light.innerCone = 0.0;
    c.reference.light.outerCone = outerCone;
}

inline void setDirectional(IndependentCase& c, glm::vec3 direction, float lux) {
    scene::Light l;
    l.name = "sun";
    l.type = scene::LightType::Directional;
    l.direction = glm::normalize(direction);
    l.position = -10.0f * l.direction;
    l.intensity = lux;
    c.module.lights = {l};
    c.reference.light.directional = true;
    c.reference.light.direction = glm::dvec3(l.direction);
    c.reference.light.intensity = lux;
}

inline scene::Camera lookAt(glm::vec3 eye, glm::vec3 target, float fovDegrees, glm::vec3 up = {0.0f, 1.0f, 0.0f}) {
    scene::Camera c;
    c.eye = eye;
    c.target = target;
    c.up = up;
    c.verticalFovRadians = glm::radians(fovDegrees);
    c.nearPlane = 0.02f;
    return c;
}

// Issue 18's scene: a glass ball (R 1, IOR 1.5) 1.6 m over the floor (centre 2.6 m up), a spot light
// straight above (9.4 m over the centre), the camera straight above (6 m over the centre). Both stand
// beyond the distance whose paraxial focus is the floor, so neither the light's nor the camera's axial
// caustic line crosses the floor, and at different distances, so the light's fold ring on the floor and
// the ring the camera's rim rays fold onto differ: where either coincides (a closer light or camera,
// or both equally far) the pixel values diverge logarithmically and no estimate converges
// (docs/physics.md, "Independent second-type reference").
inline IndependentCase ballFromAbove() {
    IndependentCase c = emptyCase("ball from above");
    addBall(c, {0.0f, 2.6f, 0.0f}, 1.0f, 1.5f);
    setSpot(c, {0.0f, 12.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, 100.0f, 0.3f);
    c.camera = lookAt({0.0f, 8.6f, 0.0f}, {0.0f, 0.0f, 0.0f}, 24.0f, {0.0f, 0.0f, -1.0f});
    c.receiverHalfSize = 4.0;
    c.axial = true;
    return c;
}

// The first guess at its set-up: centre 1.6 m up, spot 4.4 m and camera 2.9 m over the centre.
// Both fold rings land together 40-45 px from the image centre and diverge there; compared inside
// 0.8 of the ball's image radius (40 px), where the reference converges (docs/physics.md).
inline IndependentCase ballFromAboveClose() {
    IndependentCase c = emptyCase("ball from above, close");
    addBall(c, {0.0f, 1.6f, 0.0f}, 1.0f, 1.5f);
    setSpot(c, {0.0f, 6.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, 10.0f, 0.5f);
    c.camera = lookAt({0.0f, 4.5f, 0.0f}, {0.0f, 0.0f, 0.0f}, 50.0f, {0.0f, 0.0f, -1.0f});
    c.receiverHalfSize = 4.0;
    c.axial = true;
    c.regionFraction = 0.625;
    return c;
}

// The same ball seen from 15 degrees off the vertical, 6 m from its centre: the camera sees the caustic through the ball's side.
inline IndependentCase ballOblique() {
    IndependentCase c = ballFromAbove();
    c.name = "ball oblique";
    c.camera = lookAt({1.55f, 8.4f, 0.0f}, {0.0f, 2.6f, 0.0f}, 24.0f);
    return c;
}

// A glass ball under light from the upper -x side casts its caustic beside it; the camera sees it
// through a 1 cm glass plate that fills the view.
inline IndependentCase plate() {
    IndependentCase c = emptyCase("plate");
    addBall(c, {0.0f, 0.8f, 0.0f}, 0.5f, 1.5f);
    setDirectional(c, {0.6f, -1.0f, 0.0f}, 1.0f);
    c.camera = lookAt({1.6f, 1.2f, 0.0f}, {0.48f, 0.0f, 0.0f}, 25.0f);
    addPaneInFrontOfCamera(c, 0.15f, 0.15f);
    c.receiverX = 0.5;
    c.receiverHalfSize = 1.0;
    return c;
}

// A water glass (glass tube with a 2 cm bottom, water inside with a 2 mm air gap so every interface is
// glass-air or water-air in both renderers) under a spot from the -x side; the camera looks from the
// light's side through the glass at the caustic beyond it.
inline IndependentCase waterGlass() {
    IndependentCase c = emptyCase("water glass");
    addTube(c, {0.0f, 0.001f, 0.0f}, 0.2f, 0.18f, 0.5f, 0.02f, 1.5f);
    addWaterColumn(c, {0.0f, 0.023f, 0.0f}, 0.178f, 0.35f);
    setSpot(c, {-2.0f, 1.5f, 0.0f}, {0.0f, 0.25f, 0.0f}, 10.0f, 0.4f);
    c.camera = lookAt({-1.0f, 0.9f, 0.0f}, {0.35f, 0.0f, 0.0f}, 30.0f);
    c.receiverX = 0.6;
    c.receiverHalfSize = 1.2;
    return c;
}

// The polished metal ring's cardioid (light 30 degrees over the floor from +x) seen through a glass pane.
inline IndependentCase ringThroughPane() {
    IndependentCase c = emptyCase("ring through pane");
    addTube(c, {0.0f, 0.0f, 0.0f}, 0.51f, 0.5f, 0.25f, 0.0f, 0.0f);
    setDirectional(c, {-0.866f, -0.5f, 0.0f}, 1.0f);
    c.camera = lookAt({-0.1f, 1.1f, 0.5f}, {-0.15f, 0.0f, 0.0f}, 35.0f);
    addPaneInFrontOfCamera(c, 0.15f, 0.15f);
    c.receiverX = -0.15;
    c.receiverHalfSize = 0.7;
    return c;
}

}  // namespace caustics::test
