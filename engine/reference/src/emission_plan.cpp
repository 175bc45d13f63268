#include "emission_plan.h"

#include <algorithm>
#include <cmath>

namespace caustics::reference {
namespace {

void setFrame(EmissionMap& m, glm::vec3 forward) {
    m.forward = glm::normalize(forward);
    glm::vec3 hint = std::abs(m.forward.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    m.right = glm::normalize(glm::cross(m.forward, hint));
    m.up = glm::cross(m.right, m.forward);
}

uint32_t mapSizeFor(uint64_t photons, size_t maps) {
    double side = std::sqrt(double(photons) / double(maps));
    return uint32_t(std::clamp(std::llround(side), 1ll, 1ll << 15));
}

}  // namespace

uint64_t EmissionPlan::photonCount() const {
    uint64_t n = 0;
    for (const EmissionMap& m : maps) n += uint64_t(m.size) * m.size;
    return n;
}

EmissionPlan planEmission(const scene::Light& light, const WorldScene& world, uint64_t photons, bool fitToSpecular) {
    EmissionPlan plan;
    bool fit = fitToSpecular && world.hasSpecular;
    glm::vec3 targetMin = fit ? world.specularMin : world.boundsMin;
    glm::vec3 targetMax = fit ? world.specularMax : world.boundsMax;
    Sphere target = boundingSphere(targetMin, targetMax);
    Sphere scene = boundingSphere(world.boundsMin, world.boundsMax);

    if (light.type == scene::LightType::Directional) {
        EmissionMap m;
        m.orthographic = true;
        setFrame(m, light.direction);
        // Square map covering the projection of the target box's corners on the light's plane.
        float extent = 0.0f;
        for (int c = 0; c < 8; ++c) {
            glm::vec3 p((c & 1) ? targetMax.x : targetMin.x, (c & 2) ? targetMax.y : targetMin.y,
                        (c & 4) ? targetMax.z : targetMin.z);
            glm::vec3 q = p - target.centre;
            extent = std::max({extent, std::abs(glm::dot(q, m.right)), std::abs(glm::dot(q, m.up))});
        }
        m.halfExtent = std::max(extent * 1.001f, 1e-6f);
        // Start the photons outside the whole scene; parallel rays make the distance irrelevant.
        float back = glm::length(target.centre - scene.centre) + scene.radius + 1.0f;
        m.origin = target.centre - m.forward * back;
        m.size = mapSizeFor(photons, 1);
        plan.maps.push_back(m);
        return plan;
    }

    glm::vec3 toTarget = target.centre - light.position;
    float distance = glm::length(toTarget);
    if (fit && distance > 1.01f * target.radius) {
        // One perspective map fitted to the target's bounding sphere (the visibility-map frustum).
        EmissionMap m;
        m.origin = light.position;
        setFrame(m, toTarget);
        m.tanHalfAngle = target.radius / std::sqrt(distance * distance - target.radius * target.radius);
        m.size = mapSizeFor(photons, 1);
        plan.maps.push_back(m);
        return plan;
    }
    // Otherwise a cube of six 90-degree maps covers every direction (spot falloff zeroes the rest).
    const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    uint32_t size = mapSizeFor(photons, 6);
    for (const glm::vec3& axis : axes) {
        EmissionMap m;
        m.origin = light.position;
        setFrame(m, axis);
        m.tanHalfAngle = 1.0f;
        m.size = size;
        plan.maps.push_back(m);
    }
    return plan;
}

}  // namespace caustics::reference
