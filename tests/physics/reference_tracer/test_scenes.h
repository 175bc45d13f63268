#pragma once
// Analytic test geometry built directly from scene.h structs (no loader), and small helpers to
// read a reference image back in world units.
#include <functional>

#include "caustics/reference/reference_tracer.h"
#include "caustics/scene/scene.h"

namespace caustics::physics {

scene::Material diffuseMaterial(float albedo);
scene::Material glassMaterial(float ior);
scene::Material mirrorMetal(float reflectance);

// Adds mesh + instance with its own material; returns the material index.
uint32_t addObject(scene::Scene& s, scene::Mesh mesh, const scene::Material& material);

scene::Mesh makeQuadY(float y, float x0, float x1, float z0, float z1);            // normal +y
scene::Mesh makeBox(glm::vec3 min, glm::vec3 max);                                  // outward normals
scene::Mesh makeSphere(glm::vec3 centre, float radius, uint32_t segments, uint32_t rings);  // poles on x
scene::Mesh makeCylinderBand(float radius, float y0, float y1, uint32_t segments);   // outward normals
scene::Mesh makeAnnulusY(float y, float inner, float outer, uint32_t segments);      // normal +y

scene::Light directionalLight(glm::vec3 direction, float lux);

// Calls f(pixel x, pixel y, floor point, pixel footprint area on the plane y = planeY) for every
// pixel whose centre ray hits the plane in front of the camera.
void forEachPixelOnPlane(const scene::Camera& camera, uint32_t width, uint32_t height, float planeY,
                         const std::function<void(uint32_t, uint32_t, glm::vec3, float)>& f);

}  // namespace caustics::physics
