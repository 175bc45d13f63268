#include "caustics/caustic_map_plan.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace caustics {
namespace {

glm::vec4 sphereOf(glm::vec3 lo, glm::vec3 hi) { return {0.5f * (lo + hi), 0.5f * glm::length(hi - lo)}; }

void setFrame(CausticMapGpu& m, glm::vec3 forward) {
    m.forward = glm::normalize(forward);
    glm::vec3 hint = std::abs(m.forward.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    m.right = glm::normalize(glm::cross(m.forward, hint));
    m.up = glm::cross(m.right, m.forward);
}

// World -> Vulkan clip for a map: texel (i, j) of the map covers the plane points
// extent * (2 (i, j) / N - 1) along (right, up), matching shaders/common/emission.h; clip y = +up,
// so map row j grows with `up` (the shaders use the same convention when they read the map).
glm::mat4 mapViewProj(const CausticMapGpu& m, float farPlane) {
    glm::mat4 view(1.0f);   // rows: right, up, forward (camera looks along +z here)
    for (int c = 0; c < 3; ++c) {
        view[c][0] = m.right[c];
        view[c][1] = m.up[c];
        view[c][2] = m.forward[c];
    }
    view[3] = glm::vec4(-glm::dot(m.right, m.origin), -glm::dot(m.up, m.origin), -glm::dot(m.forward, m.origin), 1);
    glm::mat4 proj(0.0f);
    float n = m.nearPlane, f = farPlane;
    if (m.orthographic) {
        proj[0][0] = 1.0f / m.extent;
        proj[1][1] = 1.0f / m.extent;
        proj[2][2] = 1.0f / (f - n);
        proj[3][2] = -n / (f - n);
        proj[3][3] = 1.0f;
    } else {
        proj[0][0] = 1.0f / m.extent;
        proj[1][1] = 1.0f / m.extent;
        proj[2][2] = f / (f - n);
        proj[3][2] = -f * n / (f - n);
        proj[2][3] = 1.0f;
    }
    return proj * view;
}

// Does the cone (apex, unit axis, half-angle) touch the sphere s?
bool coneTouchesSphere(glm::vec3 apex, glm::vec3 axis, float halfAngle, glm::vec4 s) {
    glm::vec3 v = glm::vec3(s) - apex;
    float d = glm::length(v);
    if (d <= s.w) return true;
    float angle = std::acos(std::clamp(glm::dot(v / d, axis), -1.0f, 1.0f));
    return angle <= halfAngle + std::asin(std::min(1.0f, s.w / d));
}

// The instances map m must rasterise: the specular objects inside its frustum, and the occluders there
// when asked (CausticsSettings::mapOccluders).
std::vector<uint32_t> instancesInFrustum(const CausticMapGpu& m, const SpecularBounds& bounds, bool occluders) {
    std::vector<uint32_t> drawn;
    for (uint32_t i = 0; i < bounds.allInstanceSpheres.size(); ++i) {
        glm::vec4 s = bounds.allInstanceSpheres[i];
        if (!occluders && !bounds.instanceIsSpecular[i]) continue;
        if (s.w >= 0.0f && mapFrustumTouchesSphere(m, s)) drawn.push_back(i);
    }
    return drawn;
}

}  // namespace

bool mapFrustumTouchesSphere(const CausticMapGpu& m, glm::vec4 sphere) {
    glm::vec3 v = glm::vec3(sphere) - m.origin;
    float along = glm::dot(v, m.forward);
    if (m.orthographic) {
        // The square of half-side `extent` lies inside the circle of radius extent * sqrt(2).
        float lateral = glm::length(v - along * m.forward);
        return along >= -sphere.w && lateral <= m.extent * std::sqrt(2.0f) + sphere.w;
    }
    // The square frustum's corners are at tan(half-angle) * sqrt(2) off the axis on the plane z = 1.
    float halfAngle = std::atan(m.extent * std::sqrt(2.0f));
    return coneTouchesSphere(m.origin, m.forward, halfAngle, sphere);
}

SpecularBounds computeSpecularBounds(const scene::Scene& scene) {
    SpecularBounds b;
    glm::vec3 specLo(1e30f), specHi(-1e30f), allLo(1e30f), allHi(-1e30f);
    for (const scene::Instance& inst : scene.instances) {
        if (inst.mesh >= scene.meshes.size()) {
            b.allInstanceSpheres.push_back(glm::vec4(0, 0, 0, -1));
            b.instanceIsSpecular.push_back(false);
            continue;
        }
        const scene::Mesh& mesh = scene.meshes[inst.mesh];
        const bool specular = mesh.material < scene.materials.size() && scene.materials[mesh.material].isSpecular();
        b.instanceIsSpecular.push_back(specular);
        glm::vec3 lo(1e30f), hi(-1e30f);
        for (const glm::vec3& p : mesh.positions) {
            glm::vec3 w = glm::vec3(inst.transform * glm::vec4(p, 1.0f));
            lo = glm::min(lo, w);
            hi = glm::max(hi, w);
        }
        b.allInstanceSpheres.push_back(lo.x > hi.x ? glm::vec4(0, 0, 0, -1) : sphereOf(lo, hi));
        if (lo.x > hi.x) continue;
        allLo = glm::min(allLo, lo);
        allHi = glm::max(allHi, hi);
        if (!specular) continue;
        specLo = glm::min(specLo, lo);
        specHi = glm::max(specHi, hi);
        b.instanceSpheres.push_back(sphereOf(lo, hi));
    }
    if (allLo.x <= allHi.x) {
        glm::vec4 s = sphereOf(allLo, allHi);
        b.sceneCentre = glm::vec3(s);
        b.sceneRadius = s.w;
    }
    if (!b.instanceSpheres.empty()) {
        glm::vec4 s = sphereOf(specLo, specHi);
        b.centre = glm::vec3(s);
        b.radius = std::max(s.w, 1e-4f);
    }
    return b;
}

CausticMapPlan planCausticMaps(const scene::Scene& scene, const SpecularBounds& bounds, bool drawOccluders) {
    CausticMapPlan plan;
    auto skip = [&](uint32_t l, std::string why) {
        plan.skippedLights.push_back(l);
        plan.skipReasons.push_back(std::move(why));
    };
    for (uint32_t l = 0; l < scene.lights.size(); ++l) {
        const scene::Light& light = scene.lights[l];
        if (bounds.empty()) { skip(l, "the scene has no specular instance"); continue; }
        if (l >= kMaxCausticLights) { skip(l, "more than kMaxCausticLights lights"); continue; }
        if (!(light.intensity > 0.0f) || glm::length(light.color) <= 0.0f) { skip(l, "emits nothing"); continue; }
        CausticMapGpu m;
        m.light = l;
        m.intensity = light.color * light.intensity;
        glm::vec3 dir = glm::normalize(light.direction);
        if (light.type == scene::LightType::Directional) {
            m.orthographic = 1;
            setFrame(m, dir);
            m.extent = bounds.radius * 1.001f;
            // The map plane sits outside the whole scene so that every occluder between the light and
            // the specular objects is rasterised in front of them.
            float back = glm::length(bounds.centre - bounds.sceneCentre) + bounds.sceneRadius + 0.01f;
            m.origin = bounds.centre - m.forward * back;
            m.nearPlane = 0.0f;
            m.viewProj = mapViewProj(m, back + bounds.radius);
            plan.maps.push_back(m);
            plan.drawnInstances.push_back(instancesInFrustum(m, bounds, drawOccluders));
            continue;
        }
        bool spot = light.type == scene::LightType::Spot;
        if (spot) {
            m.spotAxis = dir;
            m.cosInner = std::cos(light.innerConeAngle);
            m.cosOuter = std::cos(light.outerConeAngle);
        }
        m.origin = light.position;
        glm::vec3 toTarget = bounds.centre - light.position;
        float distance = glm::length(toTarget);
        float halfAngle = kWideHalfAngle;
        glm::vec3 axis = distance > 0.0f ? toTarget / distance : (spot ? dir : glm::vec3(0, -1, 0));
        if (distance > 1.001f * bounds.radius) halfAngle = std::asin(bounds.radius / distance);
        if (spot && halfAngle >= light.outerConeAngle) {
            // The cone is the tighter frustum (texels outside the cone get zero falloff anyway).
            axis = dir;
            halfAngle = std::min(light.outerConeAngle, kWideHalfAngle);
        }
        bool any = false;
        for (const glm::vec4& s : bounds.instanceSpheres) {
            bool inFrustum = coneTouchesSphere(light.position, axis, halfAngle, s);
            bool inCone = !spot || coneTouchesSphere(light.position, dir, light.outerConeAngle, s);
            any = any || (inFrustum && inCone);
        }
        if (!any) { skip(l, "no specular instance inside its frustum/cone"); continue; }
        setFrame(m, axis);
        // The square frustum circumscribes the fitted cone: tan(half-angle) per side.
        m.extent = std::tan(halfAngle);
        m.nearPlane = std::max(1e-3f, 1e-5f * (distance + bounds.radius));
        m.viewProj = mapViewProj(m, distance + bounds.radius * 1.01f + 1e-3f);
        plan.maps.push_back(m);
        plan.drawnInstances.push_back(instancesInFrustum(m, bounds, drawOccluders));
    }
    return plan;
}

}  // namespace caustics
