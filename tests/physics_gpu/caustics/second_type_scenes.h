#pragma once
// Scenes and views of the second-type physics tests (second_type_test.cpp): a glass ball seen from
// above, the ball's caustic seen through a glass plate in front of the camera, and a thin wall that a
// caustic must not cross.
#include <glm/gtc/matrix_transform.hpp>

#include "caustics/scene/builtin_scenes.h"
#include "caustics/scene/mesh_builder.h"
#include "caustics/scene/mesh_utils.h"

namespace caustics::test {

inline uint32_t addSceneObject(scene::Scene& s, scene::Mesh mesh, scene::Material material, const glm::mat4& transform) {
    s.materials.push_back(std::move(material));
    mesh.material = uint32_t(s.materials.size() - 1);
    mesh.name = s.materials.back().name;
    s.meshes.push_back(std::move(mesh));
    uint32_t id = uint32_t(s.instances.size());
    s.instances.push_back({uint32_t(s.meshes.size() - 1), transform, id + 1});
    return id + 1;  // objectId
}

inline scene::Material glassMaterial(float ior, float thickness) {
    scene::Material m;
    m.name = "glass " + std::to_string(ior);
    m.baseColor = glm::vec3(1.0f);
    m.roughness = 0.0f;
    m.transmission = 1.0f;
    m.ior = ior;
    m.thickness = thickness;
    return m;
}

// Glass ball (IOR 1.5, R 0.4) whose centre is 0.55 m above the floor: the floor lies between the
// marginal and the paraxial focus (0.6 m below the centre), so the caustic under the ball is a central
// spike on a plateau inside a bright fold ring; the light shines straight down.
inline scene::Scene ballFromAboveScene() {
    scene::AnalyticSceneDesc d;
    d.radius = 0.4f;
    d.height = 0.55f;
    d.planeHalfSize = 2.0f;
    d.tessellation = 128;
    return scene::makeGlassSphereScene(d);
}

// Straight down onto the ball, which fills most of the view.
inline scene::Camera ballFromAboveCamera() {
    scene::Camera c;
    c.eye = {0.0f, 1.6f, 0.0f};
    c.target = {0.0f, 0.0f, 0.0f};
    c.up = {0.0f, 0.0f, -1.0f};
    c.verticalFovRadians = glm::radians(50.0f);
    return c;
}

// A glass ball (R 0.5, centre 0.8 m up) under light from the upper -x side: the caustic lands beside
// the ball around x = 0.48, where a camera on the +x side sees it directly.
inline scene::Scene sideCausticScene(float planeHalfSize = 3.0f) {
    scene::AnalyticSceneDesc d;
    d.radius = 0.5f;
    d.height = 0.8f;
    d.planeHalfSize = planeHalfSize;
    d.tessellation = 96;
    d.lightDirection = glm::normalize(glm::vec3(0.6f, -1.0f, 0.0f));
    return scene::makeGlassSphereScene(d);
}

inline scene::Camera sideCausticCamera() {
    scene::Camera c;
    c.eye = {1.6f, 1.2f, 0.0f};
    c.target = {0.48f, 0.0f, 0.0f};
    c.verticalFovRadians = glm::radians(25.0f);
    c.nearPlane = 0.02f;
    return c;
}

// A 1 cm glass plate (0.3 m square) 0.15 m in front of the eye, perpendicular to the view axis: it fills
// the view, and the light (from the upper -x side) reaches neither it nor its shadow in the view.
// thickness 0: a thin-walled pane instead (one quad, no KHR_materials_volume; docs/physics.md).
inline uint32_t addPlateInFrontOfCamera(scene::Scene& s, const scene::Camera& c, float ior, float thickness = 0.01f) {
    glm::vec3 axis = glm::normalize(c.target - c.eye);
    glm::vec3 centre = c.eye + 0.15f * axis;
    // Box local +Y (the 1 cm direction) along the view axis.
    glm::vec3 x = glm::normalize(glm::cross(axis, glm::vec3(0.0f, 1.0f, 0.0f)));
    glm::mat4 m(1.0f);
    m[0] = glm::vec4(x, 0.0f);
    m[1] = glm::vec4(axis, 0.0f);
    m[2] = glm::vec4(glm::cross(x, axis), 0.0f);
    m[3] = glm::vec4(centre, 1.0f);
    scene::Mesh plate = thickness > 0.0f ? scene::makeBox({0.15f, 0.5f * thickness, 0.15f}) : scene::makePlane(0.15f, 0.15f);
    scene::sortTrianglesMorton(plate);
    scene::Material glass = glassMaterial(ior, thickness);
    glass.doubleSided = thickness <= 0.0f;
    return addSceneObject(s, std::move(plate), glass, m);
}

// Thin wall: a diffuse wall 2 cm thick (x in [-0.01, 0.01]), 0.25 m tall, along z; a horizontal glass
// slab 0.3 m up over the +x side only; light straight down. Caustic photons (through the slab) land
// only at x >= 0.01, the wall's +x foot included; the -x side gets none. A vertical glass plate in
// front of the camera (which looks along the wall) makes every floor pixel a second-type pixel.
inline scene::Scene thinWallScene() {
    scene::AnalyticSceneDesc d;
    d.planeHalfSize = 3.0f;
    scene::Scene s = scene::makeGlassSlabScene(d);  // plane + light straight down + a slab we replace
    s.meshes.pop_back();
    s.instances.pop_back();
    s.materials.pop_back();
    scene::Material wall;
    wall.name = "wall";
    wall.baseColor = glm::vec3(0.8f);
    wall.roughness = 1.0f;
    scene::Mesh wallMesh = scene::makeBox({0.01f, 0.125f, 0.6f});
    addSceneObject(s, std::move(wallMesh), wall, glm::translate(glm::mat4(1.0f), {0.0f, 0.125f, 0.0f}));
    scene::Mesh slab = scene::makeBox({0.3f, 0.005f, 0.6f});
    addSceneObject(s, std::move(slab), glassMaterial(1.5f, 0.01f), glm::translate(glm::mat4(1.0f), {0.31f, 0.305f, 0.0f}));
    return s;
}

inline scene::Camera thinWallCamera() {
    scene::Camera c;
    c.eye = {0.0f, 0.45f, 1.3f};
    c.target = {0.0f, 0.0f, 0.0f};
    c.verticalFovRadians = glm::radians(30.0f);
    c.nearPlane = 0.02f;
    return c;
}

}  // namespace caustics::test
